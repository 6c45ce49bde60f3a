#!/usr/bin/python3
"""Composes the pictures of the shadow-map variants (docs/methods.md, issue
22) from renders written by scripts/map-variant-pictures.sh: a panel is a
render's beauty PNG, optionally with its mistakes against the exact render
painted (red: false lit, cyan: false shadowed, from the shadow.0 planes
exported as PNG), or the difference of two beauty PNGs, magnified.

Usage: map_variant_figure.py OUT.png COLUMNS PANEL...
  PANEL = beauty|TITLE|BEAUTY.png[|SHADOW.png|EXACT_SHADOW.png]
        | diff|TITLE|A.png|B.png|GAIN
"""
import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import numpy as np  # noqa: E402

from failure_figure import run  # noqa: E402  (the panel layout, beside this script)


def rgb(path):
    image = mpimg.imread(path)
    return image[..., :3] if image.ndim == 3 else np.stack([image] * 3, axis=-1)


def plane(path):
    image = mpimg.imread(path)
    return image if image.ndim == 2 else image[..., 0]


def panel(parts):
    kind, title = parts[0], parts[1]
    if kind == "diff":
        a, b, gain = rgb(parts[2]), rgb(parts[3]), float(parts[4])
        return np.clip((a - b) * gain, 0, 1), title, None
    image = rgb(parts[2])
    if len(parts) < 5:
        return image, title, None
    # Mistakes over the dimmed picture: shadow.0 is 1 lit, 0 shadowed.
    mine, truth = plane(parts[3]), plane(parts[4])
    out = image * 0.6
    false_lit = (mine > 0.75) & (truth < 0.25)
    false_shadowed = (mine < 0.25) & (truth > 0.75)
    out[false_lit] = (1.0, 0.15, 0.1)
    out[false_shadowed] = (0.1, 0.75, 1.0)
    counts = f"{int(false_lit.sum())} false lit, {int(false_shadowed.sum())} false shadowed"
    return out, title, counts


def titled(parts):
    image, title, counts = panel(parts)
    return image, title + (f"\n{counts}" if counts else "")


def main():
    run(titled, legend="red: false lit (light leaks)   cyan: false shadowed (acne, spurious "
        "shadow)", width=3.3, height=3.5, dpi=80)


if __name__ == "__main__":
    main()
