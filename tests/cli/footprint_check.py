#!/usr/bin/env python3
"""Reads an `umbra footprint` PLY and its CSV independently of umbra and
checks that they agree: every region a polygon of 3+ vertices with valid
class and facing; per (light, model, polygon), the regions' areas (Newell's
formula on the file's doubles) add up to the CSV's area, the lit ones to
its lit area; lit + shadowed = area; a receiver facing 0 has no lit region.
With coloured shadows (tau_r/g/b on the faces): every τ in [0, 1], 1 on lit
regions; and for a receiver facing the light the CSV's sunlit fraction is
(lit area + Σ shadowed area · mean τ) / area (docs/transmittance.md).
Usage: footprint_check.py OUT.ply OUT.csv   (exit 0 when all hold)
"""
import csv
import math
import struct
import sys
from collections import defaultdict

TYPES = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I",
         "float": "f", "double": "d", "int8": "b", "uint8": "B", "int32": "i", "uint32": "I",
         "float64": "d"}


def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    assert header[0] == "ply" and header[1] == "format binary_little_endian 1.0", header[:2]
    elements, current = [], None
    for line in header[2:]:
        words = line.split()
        if words[0] == "element":
            current = (words[1], int(words[2]), [])
            elements.append(current)
        elif words[0] == "property":
            current[2].append(words[1:])
    pos = end
    vertices, faces = [], []
    for name, count, props in elements:
        for _ in range(count):
            row = {}
            for prop in props:
                if prop[0] == "list":
                    n = struct.unpack_from("<" + TYPES[prop[1]], data, pos)[0]
                    pos += struct.calcsize(TYPES[prop[1]])
                    fmt = "<%d%s" % (n, TYPES[prop[2]])
                    row[prop[3]] = struct.unpack_from(fmt, data, pos)
                    pos += struct.calcsize(fmt)
                else:
                    fmt = "<" + TYPES[prop[0]]
                    row[prop[1]] = struct.unpack_from(fmt, data, pos)[0]
                    pos += struct.calcsize(fmt)
            (vertices if name == "vertex" else faces).append(row)
    assert pos == len(data), "trailing bytes"
    return [(v["x"], v["y"], v["z"]) for v in vertices], faces


def area(points):
    nx = ny = nz = 0.0
    for i, a in enumerate(points):
        b = points[(i + 1) % len(points)]
        nx += (a[1] - b[1]) * (a[2] + b[2])
        ny += (a[2] - b[2]) * (a[0] + b[0])
        nz += (a[0] - b[0]) * (a[1] + b[1])
    return 0.5 * math.sqrt(nx * nx + ny * ny + nz * nz)


def main():
    vertices, faces = read_ply(sys.argv[1])
    rows = list(csv.DictReader(open(sys.argv[2], newline="")))
    sums = defaultdict(lambda: [0.0, 0.0, 0])
    passed = defaultdict(float)  # shadowed area times mean τ, per receiver
    tinted = bool(faces) and "tau_r" in faces[0]
    failures = []
    for i, f in enumerate(faces):
        idx = f["vertex_indices"]
        if len(idx) < 3 or f["class"] not in (0, 1) or f["facing"] not in (-1, 0, 1) \
                or f["triangle"] < -1:
            failures.append("face %d: malformed %r" % (i, f))
            continue
        key = (f["light"], f["model"], f["polygon"])
        a = area([vertices[k] for k in idx])
        sums[key][0] += a
        if f["class"] == 1:
            sums[key][1] += a
            if f["facing"] == 0:
                failures.append("face %d: lit with the light in its plane" % i)
        sums[key][2] += 1
        if tinted:
            tau = (f["tau_r"], f["tau_g"], f["tau_b"])
            if not all(0 <= t <= 1 for t in tau) or (f["class"] == 1 and tau != (1, 1, 1)):
                failures.append("face %d: tau %r for class %d" % (i, tau, f["class"]))
            if f["class"] == 0:
                passed[key] += a * sum(tau) / 3
    seen = set()
    for r in rows:
        key = (int(r["light"]), int(r["model"]), int(r["polygon"]))
        seen.add(key)
        total, lit, count = sums.get(key, [0.0, 0.0, 0])
        a, la, sa = float(r["area"]), float(r["lit_area"]), float(r["shadowed_area"])
        tol = 1e-9 * max(1.0, a)
        if abs(total - a) > tol or abs(lit - la) > tol or abs(la + sa - a) > tol:
            failures.append("%r: regions %.17g (lit %.17g) vs csv %.17g (lit %.17g, shadowed "
                            "%.17g)" % (key, total, lit, a, la, sa))
        if a > 0 and count == 0:
            failures.append("%r: area %g but no region" % (key, a))
        if not 0 <= float(r["sunlit_fraction"]) <= 1:
            failures.append("%r: sunlit fraction %s" % (key, r["sunlit_fraction"]))
        if int(r["facing"]) == 1 and a > 0:
            expected = (lit + passed.get(key, 0.0)) / a
            if abs(expected - float(r["sunlit_fraction"])) > 1e-9:
                failures.append("%r: sunlit fraction %s, regions give %.17g" %
                                (key, r["sunlit_fraction"], expected))
    for key in sums:
        if key not in seen:
            failures.append("%r: regions but no CSV row" % (key,))
    for line in failures[:10]:
        print("footprint_check:", line)
    print("footprint_check: %d faces, %d receivers, %d failures" % (len(faces), len(rows),
                                                                     len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
