#!/usr/bin/env python3
"""Writes data/scenes/city/block.city.json, a small CityJSON 2.0 block (run from anywhere).

Six CityObjects in the manner of the 3D BAG (Dutch buildings, RD New + NAP
coordinates, EPSG:7415): integer millimetre vertices with a transform whose
translate is a real-looking RD/NAP position near Delft (x 84,616 m,
y 447,423 m, z -0.45 m NAP at street level). Every building has a LoD 1.2
block (a flat-topped prism) and a LoD 2.2 shape, both Solids whose every
surface has semantics (GroundSurface, WallSurface, RoofSurface, Window):
- b1: a flat-roofed box, 10 x 8 m, 12 m high, behind b4;
- b2: a gabled house, 8 x 10 m, eaves at 6 m, ridge at 9 m along y;
- b3: a box, 12 x 10 m, 9 m high, and its BuildingPart b3-annex, a 6 x 6 m,
  4 m high annex against its east wall (parents/children linked);
- b4: a box, 10 x 8 m, 7 m high, whose south wall (facing the sun and the
  scene's camera) has a window hole (an inner ring) closed by a Window
  surface, so the solid stays closed;
- b5: an L-shaped flat-roofed building (a non-convex footprint), 6 m high.
Outer rings run counter-clockwise seen from outside, inner rings clockwise,
as CityJSON orders them. Python 3 standard library only.
"""
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))
SCALE = [0.001, 0.001, 0.001]
TRANSLATE = [84616.468, 447422.999, -0.45]
SEMANTIC_TYPES = ["GroundSurface", "WallSurface", "RoofSurface", "Window"]
GROUND, WALL, ROOF, WINDOW = range(4)


class Vertices:
    """The file's shared vertex list: millimetre integers, each point once."""

    def __init__(self):
        self.points = []
        self.index = {}

    def __call__(self, x, y, z):
        key = (round(x * 1000), round(y * 1000), round(z * 1000))
        if key not in self.index:
            self.index[key] = len(self.points)
            self.points.append(list(key))
        return self.index[key]


def solid(surfaces):
    """A Solid of one shell from (semantic, rings) pairs."""
    return {"boundaries": [[rings for _, rings in surfaces]],
            "semantics": {"surfaces": [{"type": t} for t in SEMANTIC_TYPES],
                          "values": [[kind for kind, _ in surfaces]]}}


def prism(v, footprint, z0, z1, window=None):
    """A prism over `footprint` (counter-clockwise seen from above) from z0 to
    z1: ground, walls, flat roof. `window` (x0, x1, z0, z1) cuts a hole in
    the first wall (footprint[0] -> footprint[1], which runs along +x) and
    closes it with a Window surface."""
    n = len(footprint)
    ground = [v(x, y, z0) for x, y in reversed(footprint)]
    roof = [v(x, y, z1) for x, y in footprint]
    surfaces = [(GROUND, [ground]), (ROOF, [roof])]
    for k in range(n):
        (ax, ay), (bx, by) = footprint[k], footprint[(k + 1) % n]
        outer = [v(ax, ay, z0), v(bx, by, z0), v(bx, by, z1), v(ax, ay, z1)]
        if k == 0 and window:
            wx0, wx1, wz0, wz1 = window
            corners = [v(wx0, ay, wz0), v(wx1, ay, wz0), v(wx1, ay, wz1), v(wx0, ay, wz1)]
            hole = [corners[0], corners[3], corners[2], corners[1]]  # clockwise from outside
            surfaces.append((WALL, [outer, hole]))
            surfaces.append((WINDOW, [corners]))
        else:
            surfaces.append((WALL, [outer]))
    return solid(surfaces)


def gabled(v, x0, y0, x1, y1, eaves, ridge):
    """A gabled house on the rectangle, its ridge along y at the middle."""
    xm = (x0 + x1) / 2
    g00, g10, g11, g01 = v(x0, y0, 0), v(x1, y0, 0), v(x1, y1, 0), v(x0, y1, 0)
    e00, e10, e11, e01 = v(x0, y0, eaves), v(x1, y0, eaves), v(x1, y1, eaves), v(x0, y1, eaves)
    r0, r1 = v(xm, y0, ridge), v(xm, y1, ridge)
    return solid([
        (GROUND, [[g00, g01, g11, g10]]),
        (WALL, [[g00, g10, e10, r0, e00]]),  # south gable
        (WALL, [[g10, g11, e11, e10]]),
        (WALL, [[g11, g01, e01, r1, e11]]),  # north gable
        (WALL, [[g01, g00, e00, e01]]),
        (ROOF, [[e10, e11, r1, r0]]),  # east slope
        (ROOF, [[e01, e00, r0, r1]]),  # west slope
    ])


def rectangle(x0, y0, x1, y1):
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def building(lod12, lod22, kind="Building", **links):
    return dict({"type": kind,
                 "attributes": {"source": "umbra data/scenes/city/make_block.py"},
                 "geometry": [dict(type="Solid", lod="1.2", **lod12),
                              dict(type="Solid", lod="2.2", **lod22)]}, **links)


def block():
    v = Vertices()
    objects = {}
    objects["b1"] = building(prism(v, rectangle(5, 22, 15, 30), 0, 11.5),
                             prism(v, rectangle(5, 22, 15, 30), 0, 12))
    objects["b2"] = building(prism(v, rectangle(20, 5, 28, 15), 0, 7.5),
                             gabled(v, 20, 5, 28, 15, 6, 9))
    objects["b3"] = building(prism(v, rectangle(35, 5, 47, 15), 0, 8.5),
                             prism(v, rectangle(35, 5, 47, 15), 0, 9), children=["b3-annex"])
    objects["b3-annex"] = building(prism(v, rectangle(47, 7, 53, 13), 0, 3.5),
                                   prism(v, rectangle(47, 7, 53, 13), 0, 4),
                                   kind="BuildingPart", parents=["b3"])
    objects["b4"] = building(prism(v, rectangle(5, 5, 15, 13), 0, 6.5),
                             prism(v, rectangle(5, 5, 15, 13), 0, 7, window=(8, 12, 2, 4.5)))
    ell = [(22, 22), (36, 22), (36, 28), (28, 28), (28, 36), (22, 36)]
    objects["b5"] = building(prism(v, ell, 0, 5.5), prism(v, ell, 0, 6))
    return {"type": "CityJSON", "version": "2.0",
            "transform": {"scale": SCALE, "translate": TRANSLATE},
            "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415"},
            "CityObjects": objects, "vertices": v.points}


def write(doc, path):
    """One CityObject and one vertex per line: readable, and diffs stay small."""
    compact = dict(separators=(", ", ": "))
    lines = ["{", f' "type": "CityJSON", "version": "{doc["version"]}",',
             f' "transform": {json.dumps(doc["transform"], **compact)},',
             f' "metadata": {json.dumps(doc["metadata"], **compact)},', ' "CityObjects": {']
    items = list(doc["CityObjects"].items())
    for k, (name, obj) in enumerate(items):
        comma = "," if k + 1 < len(items) else ""
        lines.append(f"  {json.dumps(name)}: {json.dumps(obj, **compact)}{comma}")
    lines.append(" },")
    lines.append(' "vertices": [')
    for k, p in enumerate(doc["vertices"]):
        comma = "," if k + 1 < len(doc["vertices"]) else ""
        lines.append(f"  {json.dumps(p, **compact)}{comma}")
    lines += [" ]", "}"]
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    out = os.path.join(HERE, "block.city.json")
    write(block(), out)
    json.load(open(out, encoding="utf-8"))  # what was written parses
    print(f"wrote {out}")
