#!/usr/bin/python3
"""Composes error pictures written by `umbra_chart --images` into one figure
of panels, each optionally cropped and magnified with nearest-neighbour
pixels so single wrong samples stay visible.

Usage: failure_figure.py OUT.png COLUMNS PANEL...
  PANEL = IMAGE.png|TITLE[|x0,y0,x1,y1]
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402


LEGEND = ("red: false lit (light leaks)   cyan: false shadowed (acne, spurious shadow)   "
          "yellow: range disagrees")


def compose(out, columns, panels, legend=LEGEND, width=4.2, height=3.4, dpi=100):
    """Writes OUT: the (image, title) pairs in rows of COLUMNS, nearest-neighbour
    pixels, the legend below."""
    rows = (len(panels) + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(width * columns, height * rows),
                             squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    for ax, (image, title) in zip(axes.flat, panels):
        ax.imshow(image, interpolation="nearest")
        ax.set_title(title, fontsize=9 if dpi >= 100 else 8)
    fig.text(0.5, 0.005, legend, ha="center", fontsize=9 if dpi >= 100 else 8)
    fig.tight_layout(rect=(0, 0.03, 1, 0.97))
    fig.savefig(out, dpi=dpi)


def run(panel_of, **layout):
    """The command line of both figure scripts: OUT.png COLUMNS PANEL...,
    each PANEL split at '|' and made an (image, title) pair by PANEL_OF."""
    if len(sys.argv) < 4:
        sys.exit(sys.modules["__main__"].__doc__)
    out, columns, specs = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    compose(out, columns, [panel_of(spec.split("|")) for spec in specs], **layout)


def cropped(parts):
    image = mpimg.imread(parts[0])
    if len(parts) > 2:
        x0, y0, x1, y1 = (int(v) for v in parts[2].split(","))
        image = image[y0:y1, x0:x1]
    return image, parts[1]


def main():
    run(cropped)


if __name__ == "__main__":
    main()
