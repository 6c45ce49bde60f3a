#!/usr/bin/python3
"""Draws the sun hours `umbra footprint SCENE --sun-times ... -o HOURS.ply`
wrote (docs/sun.md, "Sun hours") as a plan: every region whose receiver
faces up, seen from above, coloured by its hours of sun, with a colour bar;
regions with fewer than --hours (default 2, BRE 209's) hatched.

Usage: sun_hours_plot.py HOURS.ply -o OUT.png [--up x|y|z] [--hours H] [--title T]
         [--dpi N] [--width-in W]

The PLY is read with footprint_plot.py's reader (struct only, no umbra); a
malformed file is refused with one line on stderr, exit 1.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import footprint_plot as fp  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib import colormaps  # noqa: E402
from matplotlib.colors import Normalize  # noqa: E402
from matplotlib.cm import ScalarMappable  # noqa: E402

PROG = "sun_hours_plot"
FACE_FIELDS = ("model", "polygon", "lit_steps", "lit_runs", "sun_hours")


def read_hours(path):
    """(points, sun_hours) per face of a sun-hours PLY, checked."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise fp.BadInput("cannot read: %s" % (e.strerror or e))
    elements, pos = fp.parse_header(data)
    props = {name: {p[1] for p in ps} for name, _, ps in elements}
    missing = [n for n in FACE_FIELDS if n not in props.get("face", ())]
    if missing or "vertex" not in props:
        raise fp.BadInput("not a sun-hours PLY (no face property %s)" % ", ".join(missing))
    rows = {}
    for name, count, ps in elements:
        rows[name], pos = fp.read_element(data, pos, name, count, ps)
    vertices = [(v["x"], v["y"], v["z"]) for v in rows["vertex"]]
    out = []
    for i, f in enumerate(rows["face"]):
        idx = f["vertex_indices"]
        if len(idx) < 3 or any(not 0 <= k < len(vertices) for k in idx):
            raise fp.BadInput("face %d: bad vertex indices" % i)
        if not (0 <= f["lit_runs"] <= f["lit_steps"]) or f["sun_hours"] < 0:
            raise fp.BadInput("face %d: lit_steps %d, lit_runs %d, sun_hours %r" % (
                i, f["lit_steps"], f["lit_runs"], f["sun_hours"]))
        out.append(([vertices[k] for k in idx], f["sun_hours"]))
    return out


def main(argv):
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    ap.add_argument("ply")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--up", choices="xyz", default="y")
    ap.add_argument("--hours", type=float, default=2.0)
    ap.add_argument("--title", default=None)
    ap.add_argument("--dpi", type=int, default=150)
    ap.add_argument("--width-in", type=float, default=7.0)
    args = ap.parse_args(argv)
    try:
        faces = read_hours(args.ply)
        a = fp.AXES[args.up]
        h, v, down = fp.TOP_VIEW[args.up]
        # Up-facing regions only, lowest first, so roofs cover the ground.
        up = [(pts, hrs) for pts, hrs in faces if fp.newell(pts)[a] > 0]
        if not up:
            raise fp.BadInput("no region faces up (--up %s)" % args.up)
        up.sort(key=lambda f: sum(p[a] for p in f[0]) / len(f[0]))
        most = max(hrs for _, hrs in up) or 1.0
        norm = Normalize(0, most)
        cmap = colormaps["inferno"]
        fig = Figure(figsize=(args.width_in, args.width_in * 0.8))
        ax = fig.add_subplot(111)
        polys = [[(p[h], p[v]) for p in pts] for pts, _ in up]
        # Layer by layer from the lowest (the ground, then roofs): the
        # regions in their colours, edges in the faces' own (no seams), then
        # those under --hours hatched, so that a roof covers the ground's
        # hatching beneath it and BRE 209's failing part reads at a glance.
        layers = {}
        for poly, (pts, hrs) in zip(polys, up):
            level = round(sum(p[a] for p in pts) / len(pts), 6)
            layers.setdefault(level, []).append((poly, hrs))
        for level in sorted(layers):
            group = layers[level]
            ax.add_collection(PolyCollection(
                [poly for poly, _ in group], facecolors=[cmap(norm(hrs)) for _, hrs in group],
                edgecolors="face", linewidths=0.3))
            short = [poly for poly, hrs in group if hrs < args.hours]
            if short:
                ax.add_collection(PolyCollection(short, facecolors="none",
                                                 edgecolors=(1, 1, 1, 0.5), linewidths=0,
                                                 hatch="////"))
        ax.autoscale_view()
        ax.set_aspect("equal")
        if down:
            ax.invert_yaxis()
        bar = fig.colorbar(ScalarMappable(norm=norm, cmap=cmap), ax=ax, label="hours of sun")
        bar.ax.axhline(args.hours, color="white", linewidth=1.5)
        ax.set_title(args.title or "%s: sun hours (hatched: under %g h)" % (
            os.path.basename(args.ply), args.hours))
        fp.write_png_atomically(fig, args.output, args.dpi)
    except fp.BadInput as e:
        print("%s: %s: %s" % (PROG, args.ply, e), file=sys.stderr)
        return 1
    print("%s: %d regions facing up drawn to %s" % (PROG, len(up), args.output))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
