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


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    out, columns, panels = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    rows = (len(panels) + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(4.2 * columns, 3.4 * rows), squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    for ax, panel in zip(axes.flat, panels):
        parts = panel.split("|")
        image = mpimg.imread(parts[0])
        if len(parts) > 2:
            x0, y0, x1, y1 = (int(v) for v in parts[2].split(","))
            image = image[y0:y1, x0:x1]
        ax.imshow(image, interpolation="nearest")
        ax.set_title(parts[1], fontsize=9)
    fig.text(0.5, 0.005, "red: false lit (light leaks)   cyan: false shadowed (acne, spurious "
             "shadow)   yellow: range disagrees", ha="center", fontsize=9)
    fig.tight_layout(rect=(0, 0.03, 1, 0.97))
    fig.savefig(out, dpi=100)


if __name__ == "__main__":
    main()
