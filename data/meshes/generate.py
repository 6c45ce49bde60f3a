#!/usr/bin/env python3
"""Writes the meshes of data/meshes/. Run from anywhere; the files are checked
in, so this is only needed to change them. Coordinates are rounded to
multiples of 1/4096 so the text denotes them exactly as doubles."""
import math
import pathlib

HERE = pathlib.Path(__file__).resolve().parent


def q(x):
    return round(x * 4096) / 4096


def write_off(name, vertices, faces, comment):
    lines = ["OFF", f"# {comment}", f"{len(vertices)} {len(faces)} 0"]
    lines += [" ".join(repr(q(c)) for c in v) for v in vertices]
    lines += [" ".join(str(i) for i in [len(f)] + list(f)) for f in faces]
    (HERE / name).write_text("\n".join(lines) + "\n")


def floor(n=4, half=8.0):
    """An n x n grid of quads in the plane y = 0, facing +y."""
    verts = [(-half + 2 * half * i / n, 0.0, -half + 2 * half * j / n)
             for j in range(n + 1) for i in range(n + 1)]
    faces = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            faces.append((a, a + n + 1, a + n + 2, a + 1))  # CCW seen from +y
    write_off("floor.off", verts, faces, "floor: 4x4 quads in y = 0, front side up")


def torus(major=1.0, minor=0.35, nu=24, nv=12):
    """A closed torus of quads about the y axis; its quads are not exactly
    planar once rounded, so they exercise the fan triangulation."""
    verts = []
    for i in range(nu):
        u = 2 * math.pi * i / nu
        for j in range(nv):
            v = 2 * math.pi * j / nv
            r = major + minor * math.cos(v)
            verts.append((r * math.cos(u), minor * math.sin(v), r * math.sin(u)))
    faces = []
    for i in range(nu):
        for j in range(nv):
            a = i * nv + j
            b = ((i + 1) % nu) * nv + j
            c = ((i + 1) % nu) * nv + (j + 1) % nv
            d = i * nv + (j + 1) % nv
            faces.append((a, d, c, b))  # outward
    write_off("torus.off", verts, faces, "closed torus, 24 x 12 quads, outward facing")


def open_box(s=0.6):
    """A cube of half-size s without its top face: an open model with four
    boundary edges."""
    verts = [(x, y, z) for z in (-s, s) for y in (-s, s) for x in (-s, s)]
    # index = 4*zi + 2*yi + xi
    faces = [
        (0, 2, 3, 1),  # z = -s, outward -z
        (4, 5, 7, 6),  # z = +s
        (0, 4, 6, 2),  # x = -s
        (1, 3, 7, 5),  # x = +s
        (0, 1, 5, 4),  # y = -s (bottom)
    ]
    write_off("open_box.off", verts, faces, "cube without its top: 5 quads, 4 boundary edges")


def cube(s=0.75):
    verts = [(x, y, z) for z in (-s, s) for y in (-s, s) for x in (-s, s)]
    faces = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3)]
    write_off("cube.off", verts, faces, "closed cube, outward facing quads")


if __name__ == "__main__":
    floor()
    torus()
    open_box()
    cube()
