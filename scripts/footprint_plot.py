#!/usr/bin/python3
"""Draws a shadow footprint written by `umbra footprint SCENE -o OUT.ply`
(docs/footprints.md): every region of one light, lit warm, shadowed dark
blue, regions whose receiver faces away from the light (facing 0 or -1) grey
(pale grey where such a region is class 1: the light reaches its back).

Usage: footprint_plot.py FOOTPRINT.ply -o OUT.png [--view top|plane] [--up x|y|z]
         [--light L] [--model M] [--polygon P] [--title T] [--dpi N] [--width-in W]

The PLY is read here with struct only (no umbra, no PLY library), generically
from its header; a malformed file is refused with one line on stderr, exit 1.
"""
import argparse
import math
import os
import struct
import sys
import tempfile
from collections import namedtuple

import matplotlib

matplotlib.use("Agg")  # files only: never look for a display, whatever else imports pyplot
from matplotlib.figure import Figure  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

PROG = "footprint_plot"

LIT = "#f3e3b0"
SHADOWED = "#27346b"
FACING_AWAY = "#8d97ab"
BACK_LIT = "#d3d9e4"
EDGE = (0.08, 0.08, 0.12, 0.55)  # translucent, so dense small regions stay readable

# PLY scalar types (both the classic and the sized names) to struct codes.
PLY_TYPES = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I",
             "float": "f", "double": "d", "int8": "b", "uint8": "B", "int16": "h",
             "uint16": "H", "int32": "i", "uint32": "I", "float32": "f", "float64": "d"}
INTEGER_CODES = set("bBhHiI")
FACE_INTS = ("light", "model", "polygon", "triangle", "class", "facing")

AXES = {"x": 0, "y": 1, "z": 2}
# The top view per up axis: (horizontal axis, vertical axis, vertical axis
# points down the page). Each is right-handed seen from above: screen right
# x screen up = the up axis, toward the viewer. For +y up this is looking
# down -y with the camera's up = -z, so x runs right and z runs DOWN the page,
# which matches a render from a camera on the +z side (near objects low).
TOP_VIEW = {"y": (0, 2, True), "z": (0, 1, False), "x": (1, 2, False)}

Region = namedtuple("Region", "light model polygon triangle cls facing points")


class BadInput(Exception):
    """A file or an option that cannot be drawn; main prints it as one line."""


# ---------------------------------------------------------------- reading

def parse_header(data):
    """Returns (elements, data offset); elements are (name, count, props) with
    props ("scalar", name, code) or ("list", name, count code, item code)."""
    if not data.startswith(b"ply\n"):
        raise BadInput("not a PLY file (no 'ply' line)")
    end = data.find(b"end_header\n")
    if end < 0:
        raise BadInput("PLY header has no end_header line")
    try:
        lines = data[:end].decode("ascii").split("\n")[1:]
    except UnicodeDecodeError:
        raise BadInput("PLY header is not ASCII")
    elements, seen_format = [], False
    for number, line in enumerate(lines, start=2):
        words = line.split()
        if not words or words[0] in ("comment", "obj_info"):
            continue
        where = "PLY header line %d" % number
        if words[0] == "format":
            if words[1:] != ["binary_little_endian", "1.0"]:
                raise BadInput("%s: only 'format binary_little_endian 1.0' is read, not %r"
                               % (where, " ".join(words[1:])))
            seen_format = True
        elif words[0] == "element":
            if len(words) != 3 or not words[2].isdigit():
                raise BadInput("%s: malformed element line %r" % (where, line))
            elements.append((words[1], int(words[2]), []))
        elif words[0] == "property":
            if not elements:
                raise BadInput("%s: property before any element" % where)
            props = elements[-1][2]
            if len(words) == 5 and words[1] == "list":
                count, item = PLY_TYPES.get(words[2]), PLY_TYPES.get(words[3])
                if count not in INTEGER_CODES or item is None:
                    raise BadInput("%s: bad list types in %r" % (where, line))
                props.append(("list", words[4], count, item))
            elif len(words) == 3 and words[1] in PLY_TYPES:
                props.append(("scalar", words[2], PLY_TYPES[words[1]]))
            else:
                raise BadInput("%s: malformed property line %r" % (where, line))
            if [p[1] for p in props].count(props[-1][1]) > 1:
                raise BadInput("%s: property %r twice" % (where, props[-1][1]))
        else:
            raise BadInput("%s: unknown keyword %r" % (where, words[0]))
    if not seen_format:
        raise BadInput("PLY header has no format line")
    return elements, end + len(b"end_header\n")


def read_element(data, pos, name, count, props):
    """Reads `count` rows; returns (list of dicts, new offset). Consecutive
    scalars are unpacked by one precompiled Struct, since per-value unpacking
    is what makes a large footprint slow to read."""
    chunks, run = [], []
    for p in props:
        if p[0] == "scalar":
            run.append(p)
            continue
        if run:
            chunks.append(("scalars", [q[1] for q in run],
                           struct.Struct("<" + "".join(q[2] for q in run))))
            run = []
        chunks.append(("list", p[1], struct.Struct("<" + p[2]), p[3]))
    if run:
        chunks.append(("scalars", [q[1] for q in run],
                       struct.Struct("<" + "".join(q[2] for q in run))))
    rows, size = [], len(data)
    for i in range(count):
        row = {}
        for chunk in chunks:
            if chunk[0] == "scalars":
                s = chunk[2]
                if pos + s.size > size:
                    raise BadInput("file ends inside %s %d of %d" % (name, i, count))
                row.update(zip(chunk[1], s.unpack_from(data, pos)))
                pos += s.size
            else:
                s = chunk[2]
                if pos + s.size > size:
                    raise BadInput("file ends inside %s %d of %d" % (name, i, count))
                n = s.unpack_from(data, pos)[0]
                pos += s.size
                if n < 0:
                    raise BadInput("%s %d: negative list length %d" % (name, i, n))
                items = struct.Struct("<%d%s" % (n, chunk[3]))
                if pos + items.size > size:
                    raise BadInput("file ends inside %s %d of %d" % (name, i, count))
                row[chunk[1]] = items.unpack_from(data, pos)
                pos += items.size
        rows.append(row)
    return rows, pos


def read_footprint(path):
    """The regions of an umbra footprint PLY, each with its points resolved
    and checked (indices in range, class 0/1, facing -1/0/+1)."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise BadInput("cannot read: %s" % (e.strerror or e))
    elements, pos = parse_header(data)
    check_layout(elements)
    rows = {}
    for name, count, props in elements:
        rows[name], pos = read_element(data, pos, name, count, props)
    if pos != len(data):
        raise BadInput("%d bytes after the last element" % (len(data) - pos))
    vertices = [(v["x"], v["y"], v["z"]) for v in rows["vertex"]]
    for i, v in enumerate(vertices):
        if not all(math.isfinite(c) for c in v):
            raise BadInput("vertex %d is not finite: %r" % (i, v))
    regions = []
    for i, f in enumerate(rows["face"]):
        idx = f["vertex_indices"]
        if len(idx) < 3:
            raise BadInput("face %d has %d vertices (a region needs 3+)" % (i, len(idx)))
        bad = [k for k in idx if not 0 <= k < len(vertices)]
        if bad:
            raise BadInput("face %d: vertex index %d out of range (%d vertices)"
                           % (i, bad[0], len(vertices)))
        if f["class"] not in (0, 1) or f["facing"] not in (-1, 0, 1) or f["triangle"] < -1 \
                or min(f["light"], f["model"], f["polygon"]) < 0:
            raise BadInput("face %d: attributes out of range: %s" % (
                i, ", ".join("%s %d" % (k, f[k]) for k in FACE_INTS)))
        regions.append(Region(f["light"], f["model"], f["polygon"], f["triangle"], f["class"],
                              f["facing"], [vertices[k] for k in idx]))
    return regions


def check_layout(elements):
    """The properties this script draws from must be there with usable types;
    their order and any extra properties or elements do not matter."""
    names = [name for name, _, _ in elements]
    for name in set(names):
        if names.count(name) > 1:
            raise BadInput("PLY has element %r twice" % name)
    props = {name: {p[1]: p for p in ps} for name, _, ps in elements}
    for element in ("vertex", "face"):
        if element not in props:
            raise BadInput("PLY has no '%s' element" % element)
    for axis in "xyz":
        p = props["vertex"].get(axis)
        if p is None or p[0] != "scalar":
            raise BadInput("vertex element has no scalar property %r" % axis)
    p = props["face"].get("vertex_indices")
    if p is None or p[0] != "list" or p[3] not in INTEGER_CODES:
        raise BadInput("face element has no integer list property 'vertex_indices'")
    for name in FACE_INTS:
        p = props["face"].get(name)
        if p is None or p[0] != "scalar" or p[2] not in INTEGER_CODES:
            raise BadInput("face element has no integer property %r" % name)


# ---------------------------------------------------------------- geometry

def newell(points):
    """Newell's vector: normal direction times twice the area, exact for any
    simple planar polygon, convex or not, and robust for nearly planar ones."""
    nx = ny = nz = 0.0
    n = len(points)
    for i in range(n):
        a, b = points[i], points[(i + 1) % n]
        nx += (a[1] - b[1]) * (a[2] + b[2])
        ny += (a[2] - b[2]) * (a[0] + b[0])
        nz += (a[0] - b[0]) * (a[1] + b[1])
    return nx, ny, nz


def norm(v):
    return math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])


def area(points):
    return 0.5 * norm(newell(points))


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def unit(v):
    length = norm(v)
    return (v[0] / length, v[1] / length, v[2] / length)


def plane_basis(regions, up):
    """(u, v, n) orthonormal with u x v = n, n from Newell's formula on all
    the regions (for a non-planar polygon's fan triangles, their
    area-weighted mean). Because regions are counter-clockwise seen from the
    front, they stay counter-clockwise in (u, v): the picture is the front.
    v is the up axis projected into the plane, so walls stand upright; for a
    plane across the up axis v is the top view's page-up, so a floor looks
    the same in both views."""
    total = [0.0, 0.0, 0.0]
    for r in regions:
        for k, c in enumerate(newell(r.points)):
            total[k] += c
    if norm(total) == 0:
        raise BadInput("the receiver's regions have no area: no plane to draw in")
    n = unit(total)
    a = AXES[up]
    reference = [0.0, 0.0, 0.0]
    reference[a] = 1.0
    v = [reference[k] - dot(reference, n) * n[k] for k in range(3)]
    if norm(v) < 1e-6:
        h, vert, down = TOP_VIEW[up]
        reference = [0.0, 0.0, 0.0]
        reference[vert] = -1.0 if down else 1.0
        v = [reference[k] - dot(reference, n) * n[k] for k in range(3)]
    v = unit(v)
    u = unit(cross(v, n))
    return u, v, n


# ---------------------------------------------------------------- drawing

def select(regions, args):
    """The regions to draw and the title's light phrase; refuses a filter
    that matches nothing, naming what the file has."""
    lights = sorted({r.light for r in regions})
    if not lights:
        raise BadInput("the footprint has no regions")
    if args.light is None:
        light = lights[0]
        phrase = ("light %d of %d (default; choose with --light)" % (light, len(lights))
                  if len(lights) > 1 else "light %d" % light)
    else:
        light = args.light
        if light not in lights:
            raise BadInput("no regions for light %d (the file has lights %s)"
                           % (light, ", ".join(map(str, lights))))
        phrase = "light %d" % light
    chosen = [r for r in regions if r.light == light]
    if args.model is not None:
        chosen = [r for r in chosen if r.model == args.model]
        if not chosen:
            raise BadInput("no regions for light %d, model %d" % (light, args.model))
        phrase += ", model %d" % args.model
    if args.polygon is not None:
        chosen = [r for r in chosen if r.polygon == args.polygon]
        if not chosen:
            raise BadInput("no regions for light %d, model %d, polygon %d"
                           % (light, args.model, args.polygon))
        phrase += ", polygon %d" % args.polygon
    return chosen, phrase


def colour(r):
    # A receiver facing away from the light gets no direct light on its
    # front by definition, not because of a caster: grey, so cast shadows
    # stand out. Its regions are still classified as seen from the light
    # (docs/footprints.md), and a lit one (class 1) means the light reaches
    # the BACK, e.g. the inside of an open box, which a top view may show:
    # a paler grey keeps that visible without calling it lit.
    if r.facing != 1:
        return BACK_LIT if r.cls == 1 else FACING_AWAY
    return LIT if r.cls == 1 else SHADOWED


def top_view(regions, up):
    """2D polygons seen from above, painted back to front: sorted by mean
    height along the up axis (roofs over the ground), and at equal height a
    face turned toward the viewer after one turned away (the street over a
    building's bottom face). Painter's order by height is not exact for
    faces that overlap in cycles, but it is for the ground and box-like
    models a footprint is mostly made of."""
    a = AXES[up]
    h, v, _ = TOP_VIEW[up]

    def key(r):
        height = sum(p[a] for p in r.points) / len(r.points)
        return (height, newell(r.points)[a] > 0)

    ordered = sorted(regions, key=key)
    return ordered, [[(p[h], p[v]) for p in r.points] for r in ordered]


def plane_view(regions, up):
    u, v, _ = plane_basis(regions, up)
    return regions, [[(dot(p, u), dot(p, v)) for p in r.points] for r in regions], (u, v)


def totals(regions):
    """Lit area is the front's (facing +1, class 1); the CSV's lit_area also
    counts a back-lit region of a receiver facing away, reported apart here."""
    receivers = {(r.light, r.model, r.polygon, r.triangle) for r in regions}
    total = lit = away = back_lit = 0.0
    for r in regions:
        a = area(r.points)
        total += a
        if r.facing != 1:
            away += a
            if r.cls == 1:
                back_lit += a
        elif r.cls == 1:
            lit += a
    return len(receivers), len(regions), lit, total, away, back_lit


def fmt_area(a):
    return "%.4g" % a if a < 1e4 else "{:,.0f}".format(a)  # no exponent for big scenes


def totals_line(regions):
    receivers, count, lit, total, away, back_lit = totals(regions)
    share = 100.0 * lit / total if total > 0 else 0.0
    line = ("%d receivers, %d regions; lit area %s of %s (%.1f%%), facing away %s"
            % (receivers, count, fmt_area(lit), fmt_area(total), share, fmt_area(away)))
    if back_lit > 0:
        line += " (back lit %s)" % fmt_area(back_lit)
    return line


def fmt_vector(w):
    # Rounding residue (1e-17) is shown as 0, and + 0.0 turns -0.0 into 0.
    return "(%s)" % ", ".join("%.3g" % (0.0 if abs(c) < 1e-12 else c + 0.0) for c in w)


def draw(regions, args, phrase):
    if args.view == "top":
        ordered, polygons = top_view(regions, args.up)
        h, v, down = TOP_VIEW[args.up]
        names = "xyz"
        xlabel = "%s (right)" % names[h]
        ylabel = "%s (%s the page)" % (names[v], "down" if down else "up")
        view_note = "top view, +%s toward the viewer" % args.up
    else:
        ordered, polygons, (u, v) = plane_view(regions, args.up)
        xlabel = "u = %s" % fmt_vector(u)
        ylabel = "v = %s" % fmt_vector(v)
        down = False
        view_note = "receiver's plane, seen from its front"

    xs = [p[0] for poly in polygons for p in poly]
    ys = [p[1] for poly in polygons for p in poly]
    width, height = max(xs) - min(xs), max(ys) - min(ys)
    # The figure takes the data's aspect so equal-aspect axes fill it; the
    # extra inches hold the title, the totals, the labels and the legend.
    aspect = height / width if width > 0 else 1.0
    fig_h = min(max(args.width_in * 0.82 * aspect + 1.6, 2.5), 1.4 * args.width_in)
    fig = Figure(figsize=(args.width_in, fig_h), layout="constrained")
    ax = fig.add_subplot()
    ax.add_collection(PolyCollection(polygons, facecolors=[colour(r) for r in ordered],
                                     edgecolors=[EDGE], linewidths=0.3))
    ax.set_aspect("equal")
    ax.autoscale_view()
    if down:
        ax.invert_yaxis()
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_facecolor("white")
    title = args.title if args.title is not None else "%s: %s" % (
        os.path.basename(args.footprint), phrase)
    fig.suptitle(title, fontsize=11)
    ax.set_title("%s\n%s" % (view_note, totals_line(ordered)), fontsize=8)
    handles = [Patch(facecolor=LIT, edgecolor=EDGE, label="lit"),
               Patch(facecolor=SHADOWED, edgecolor=EDGE, label="shadowed"),
               Patch(facecolor=FACING_AWAY, edgecolor=EDGE,
                     label="facing away (light behind or in plane)")]
    if any(r.facing != 1 and r.cls == 1 for r in ordered):
        handles.append(Patch(facecolor=BACK_LIT, edgecolor=EDGE,
                             label="facing away, back lit"))
    ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.1),
              ncol=len(handles), frameon=False, fontsize=8)
    return fig


def write_png_atomically(fig, out, dpi):
    """Renders to a temporary file beside OUT, then renames it over OUT, so a
    failure (disk full, interrupted) never leaves a partial picture."""
    directory = os.path.dirname(os.path.abspath(out))
    try:
        fd, tmp = tempfile.mkstemp(prefix=".%s." % os.path.basename(out), suffix=".tmp",
                                   dir=directory)
    except OSError as e:
        raise BadInput("cannot write in %s: %s" % (directory, e.strerror or e))
    try:
        with os.fdopen(fd, "wb") as f:
            fig.savefig(f, format="png", dpi=dpi)
        # mkstemp makes the file 0600; give it the mode a plain open() would.
        mask = os.umask(0)
        os.umask(mask)
        os.chmod(tmp, 0o666 & ~mask)
        os.replace(tmp, out)
    except BaseException as e:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        if isinstance(e, OSError):
            raise BadInput("cannot write %s: %s" % (out, e.strerror or e))
        raise


# ---------------------------------------------------------------- main

def parse_args(argv):
    parser = argparse.ArgumentParser(
        prog="footprint_plot.py",
        description="Draws an `umbra footprint` PLY (docs/footprints.md): the regions of one "
                    "light, lit (warm), shadowed (dark blue) and facing away from the light "
                    "(grey: facing 0 or -1, no direct light on the front by definition rather "
                    "than by a caster; pale grey where the light reaches the back).",
        epilog="--view top looks down the up axis, right-handed seen from above: for --up y "
               "(default) x runs right and z runs DOWN the page (the layout a camera on the +z "
               "side looking toward -z shows: near things low, far things high); for --up z, "
               "x right and y up; for --up x, y right and z up. Faces are painted by height, "
               "roofs over the ground. "
               "--view plane draws one receiver polygon (--model, --polygon) in its own "
               "plane, seen from its front, with v the up axis projected into the plane. "
               "Areas are Newell's formula on the file's doubles.")
    parser.add_argument("footprint", metavar="FOOTPRINT.ply")
    parser.add_argument("-o", "--output", required=True, metavar="OUT.png")
    parser.add_argument("--view", choices=("top", "plane"), default="top",
                        help="top (default): from above along --up; plane: one receiver "
                             "polygon in its own plane (needs --model and --polygon)")
    parser.add_argument("--up", choices=("x", "y", "z"), default="y",
                        help="the scene's up axis (default y)")
    parser.add_argument("--light", type=int, metavar="L",
                        help="the light to draw (default: the lowest-numbered in the file)")
    parser.add_argument("--model", type=int, metavar="M", help="only this model's regions")
    parser.add_argument("--polygon", type=int, metavar="P",
                        help="only this polygon of --model")
    parser.add_argument("--title", metavar="T", help="default: the file name and the light")
    parser.add_argument("--dpi", type=int, default=100, metavar="N", help="default 100")
    parser.add_argument("--width-in", type=float, default=7.0, metavar="W",
                        help="figure width in inches (default 7)")
    args = parser.parse_args(argv)
    if args.polygon is not None and args.model is None:
        parser.error("--polygon needs --model")
    if args.view == "plane" and (args.model is None or args.polygon is None):
        parser.error("--view plane needs --model M --polygon P")
    if not 20 <= args.dpi <= 1200:
        parser.error("--dpi must be within 20..1200")
    if not 1 <= args.width_in <= 60:
        parser.error("--width-in must be within 1..60")
    if not args.output.lower().endswith(".png"):
        parser.error("the output must be a .png file")
    return args


def main(argv):
    args = parse_args(argv)
    try:
        try:
            regions, phrase = select(read_footprint(args.footprint), args)
        except BadInput as e:
            raise BadInput("%s: %s" % (args.footprint, e))  # name the file being read
        fig = draw(regions, args, phrase)
        write_png_atomically(fig, args.output, args.dpi)
    except BadInput as e:
        print("%s: %s" % (PROG, e), file=sys.stderr)
        return 1
    print("%s: wrote %s: %s" % (PROG, args.output, totals_line(regions)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
