#!/usr/bin/env python3
"""Writes the glTF validation scenes of data/scenes/gltf/ (run from anywhere).

two_lights.gltf: a floor, a closed cube turned 30 degrees about y under a
translated parent, a triangle-strip ramp, a point light with a range and a
directional light, and a perspective camera tilted down; buffers embedded as
base64 data URIs. two_lights.glb: the same scene as a GLB container.
tinted.gltf: the same scene whose cube's material has KHR_materials_transmission
(factor 0.5): a tinted cube, T = 0.5 x its base colour (docs/transmittance.md).
"""
import base64
import json
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


class Builder:
    def __init__(self):
        self.bin = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "umbra data/scenes/gltf/generate.py"},
                    "bufferViews": [], "accessors": [], "meshes": [], "nodes": []}

    def view(self, data):
        while len(self.bin) % 4:
            self.bin += b"\0"
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)})
        self.bin += data
        return len(self.doc["bufferViews"]) - 1

    def positions(self, pts):
        data = b"".join(struct.pack("<3f", *p) for p in pts)
        lo = [min(p[k] for p in pts) for k in range(3)]
        hi = [max(p[k] for p in pts) for k in range(3)]
        self.doc["accessors"].append({"bufferView": self.view(data), "componentType": 5126,
                                      "count": len(pts), "type": "VEC3", "min": lo, "max": hi})
        return len(self.doc["accessors"]) - 1

    def indices(self, idx, ctype):
        fmt = {5121: "B", 5123: "H", 5125: "I"}[ctype]
        data = struct.pack("<%d%s" % (len(idx), fmt), *idx)
        self.doc["accessors"].append({"bufferView": self.view(data), "componentType": ctype,
                                      "count": len(idx), "type": "SCALAR"})
        return len(self.doc["accessors"]) - 1

    def mesh(self, name, pos, idx=None, mode=4, material=None):
        prim = {"attributes": {"POSITION": pos}, "mode": mode}
        if idx is not None:
            prim["indices"] = idx
        if material is not None:
            prim["material"] = material
        self.doc["meshes"].append({"name": name, "primitives": [prim]})
        return len(self.doc["meshes"]) - 1

    def node(self, **fields):
        self.doc["nodes"].append(fields)
        return len(self.doc["nodes"]) - 1


def quat(axis, deg):
    h = math.radians(deg) / 2
    n = math.sqrt(sum(a * a for a in axis))
    return [a / n * math.sin(h) for a in axis] + [math.cos(h)]


def build():
    b = Builder()
    b.doc["materials"] = [
        {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1]}},
        {"name": "cube", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.4, 0.3, 1]}},
        {"name": "ramp", "pbrMetallicRoughness": {"baseColorFactor": [0.3, 0.6, 0.9, 1]}},
    ]
    floor = b.mesh("floor", b.positions([(-6, 0, -6), (6, 0, -6), (6, 0, 6), (-6, 0, 6)]),
                   b.indices([0, 2, 1, 0, 3, 2], 5121), material=0)
    # Closed unit cube, counter-clockwise seen from outside, 16-bit indices.
    cube_pts = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
    cube_idx = [0, 2, 3, 0, 3, 1,  4, 5, 7, 4, 7, 6,  0, 1, 5, 0, 5, 4,
                2, 6, 7, 2, 7, 3,  0, 4, 6, 0, 6, 2,  1, 3, 7, 1, 7, 5]
    cube = b.mesh("cube", b.positions(cube_pts), b.indices(cube_idx, 5123), material=1)
    # A ramp as a triangle strip without indices (front side up).
    ramp = b.mesh("ramp", b.positions([(0, 0.01, 0), (0, 0.01, 1.5), (2, 0.8, 0), (2, 0.8, 1.5)]),
                  mode=5, material=2)
    b.doc["cameras"] = [{"name": "view", "type": "perspective",
                         "perspective": {"yfov": math.radians(45), "aspectRatio": 4 / 3, "znear": 0.1},
                         "extras": {"umbra": {"width": 320, "height": 240}}}]
    b.doc["extensionsUsed"] = ["KHR_lights_punctual"]
    b.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "lamp", "type": "point", "color": [1, 0.95, 0.9], "intensity": 1, "range": 16},
        {"name": "sun", "type": "directional", "intensity": 0.4},
    ]}}
    n_floor = b.node(name="floor", mesh=floor)
    n_cube = b.node(name="cube", mesh=cube, rotation=quat((0, 1, 0), 30), scale=[1.5, 1.5, 1.5])
    n_group = b.node(name="group", translation=[-1, 0, -0.5], children=[n_cube])
    n_ramp = b.node(name="ramp", mesh=ramp, translation=[1.5, 0, 1])
    # The sun travels along its local -Z, turned down by 60 degrees and to the side.
    n_sun = b.node(name="sun", rotation=quat((-1, 0.5, 0), 55),
                   extensions={"KHR_lights_punctual": {"light": 1}})
    n_lamp = b.node(name="lamp", translation=[3, 6, 2], extensions={"KHR_lights_punctual": {"light": 0}})
    n_cam = b.node(name="camera", camera=0, translation=[0, 4, 9], rotation=quat((1, 0, 0), -24))
    b.doc["scenes"] = [{"nodes": [n_floor, n_group, n_ramp, n_sun, n_lamp, n_cam]}]
    b.doc["scene"] = 0
    return b


def write_tinted():
    b = build()
    doc = dict(b.doc)
    doc["materials"][1]["extensions"] = {"KHR_materials_transmission": {"transmissionFactor": 0.5}}
    doc["extensionsUsed"] = ["KHR_lights_punctual", "KHR_materials_transmission"]
    doc["buffers"] = [{"byteLength": len(b.bin),
                       "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(b.bin)).decode()}]
    with open(os.path.join(HERE, "tinted.gltf"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def main():
    write_tinted()
    b = build()
    doc = dict(b.doc)
    doc["buffers"] = [{"byteLength": len(b.bin),
                       "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(b.bin)).decode()}]
    with open(os.path.join(HERE, "two_lights.gltf"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    doc["buffers"] = [{"byteLength": len(b.bin)}]
    js = json.dumps(doc).encode()
    js += b" " * (-len(js) % 4)
    body = bytes(b.bin) + b"\0" * (-len(b.bin) % 4)
    total = 12 + 8 + len(js) + 8 + len(body)
    with open(os.path.join(HERE, "two_lights.glb"), "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, total))
        f.write(struct.pack("<II", len(js), 0x4E4F534A) + js)
        f.write(struct.pack("<II", len(body), 0x004E4942) + body)


if __name__ == "__main__":
    main()
