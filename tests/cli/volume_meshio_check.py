#!/usr/bin/python3
"""Reads `umbra volume` exports of one scene with meshio (Debian's
python3-meshio, hence /usr/bin/python3) and checks what it keeps against the
binary PLY, parsed here independently of umbra and of meshio
(footprint_check.read_ply):

- the ASCII PLY (--ply-format ascii): every face with its vertices' exact
  doubles and every face property, `face` naming its polygon in the export;
- the OBJ: the faces of each (light, type) as one cell set (meshio's
  `obj:group_ids`, the group's ordinal), the `g` lines naming them
  light<L>_near_cap|_side|_far_cap in light then type order, with the
  group's face count and vertex counts, and every face's exact doubles
  (the sidecar's `face` maps the OBJ's faces to the PLY's);
- the binary PLY: meshio 7.0.0 cannot read it (its binary reader expects a
  face element's list for all faces before the other properties; umbra's
  faces carry properties after each list), the limit docs/volume-export.md
  states. If a newer meshio reads it, this says so and fails, so that the
  documentation gets updated.

Usage: volume_meshio_check.py BINARY.ply ASCII.ply OUT.obj   (exit 0 when all hold)
"""
import collections
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from footprint_check import read_ply  # noqa: E402  (the independent binary PLY reader)

try:
    import meshio
except ImportError:
    print("SKIP: meshio is missing (Debian's python3-meshio; scripts/install-deps.sh)")
    sys.exit(77)

PROPERTIES = ["light", "model", "polygon", "edge", "type", "nb_c", "twisted"]
TYPE_NAMES = {1: "near_cap", 2: "side", 3: "far_cap"}


def flatten(blocks):
    """meshio's cell blocks (or per-block cell data) as one list, in order."""
    return [row for block in blocks for row in block]


def check_ascii_ply(path, vertices, faces, failures):
    mesh = meshio.read(path)
    cells = flatten(block.data for block in mesh.cells)
    if len(cells) != len(faces):
        failures.append("ascii PLY: %d cells, the binary PLY has %d faces" % (len(cells), len(faces)))
        return
    data = {name: flatten(mesh.cell_data[name]) for name in PROPERTIES + ["face"]}
    seen = collections.Counter()
    for i, cell in enumerate(cells):
        f = int(data["face"][i])
        seen[f] += 1
        want = faces[f]
        for name in PROPERTIES:
            if int(data[name][i]) != want[name]:
                failures.append("ascii PLY cell %d (face %d): %s %d, want %d" %
                                (i, f, name, data[name][i], want[name]))
        got = [tuple(float(c) for c in mesh.points[v]) for v in cell]
        expected = [vertices[v] for v in want["vertex_indices"]]
        if got != expected:  # exact: both are the file's doubles
            failures.append("ascii PLY cell %d (face %d): vertices differ" % (i, f))
    if sorted(seen) != list(range(len(faces))) or max(seen.values(), default=1) != 1:
        failures.append("ascii PLY: `face` is not each export index once")


def check_obj(path, vertices, faces, failures):
    # Expected groups from the binary PLY's own face properties.
    want = collections.OrderedDict()
    for key in sorted({(f["light"], f["type"]) for f in faces}):
        want[key] = collections.Counter()
    for f in faces:
        want[(f["light"], f["type"])][len(f["vertex_indices"])] += 1
    names = ["light%d_%s" % (light, TYPE_NAMES[t]) for light, t in want]
    with open(path) as text:
        lines = text.read().splitlines()
    groups = [line.split()[1] for line in lines if line.startswith("g ")]
    materials = [line.split()[1] for line in lines if line.startswith("usemtl ")]
    if groups != names or materials != names:
        failures.append("OBJ: groups %s, materials %s; want %s" % (groups, materials, names))

    mesh = meshio.read(path)
    got = collections.defaultdict(collections.Counter)
    for block, ids in zip(mesh.cells, mesh.cell_data["obj:group_ids"]):
        for cell, gid in zip(block.data, ids):
            got[int(gid)][len(cell)] += 1
    # Cells come in the file's face order; the sidecar's `face` names each
    # one's export index, whose vertices the binary PLY holds.
    with open(path + ".json") as sidecar:
        export_index = json.load(sidecar)["attributes"]["face"]
    cells = flatten(block.data for block in mesh.cells)
    for i, cell in enumerate(cells):
        got_points = [tuple(float(c) for c in mesh.points[v]) for v in cell]
        if got_points != [vertices[v] for v in faces[export_index[i]]["vertex_indices"]]:
            failures.append("OBJ cell %d (face %d): vertices differ" % (i, export_index[i]))
            break
    for gid, (key, sizes) in enumerate(want.items()):
        if got.get(gid) != sizes:
            failures.append("OBJ group %d (%s): meshio has faces by vertex count %s, want %s" %
                            (gid, names[gid], dict(got.get(gid, {})), dict(sizes)))
    if len(got) != len(want):
        failures.append("OBJ: meshio has %d groups, want %d" % (len(got), len(want)))
    return len(want)


def check_binary_ply(path, failures):
    try:
        meshio.read(path)
    except Exception as error:  # meshio raises several types; any refusal counts
        return "refused (%s: %s)" % (type(error).__name__, str(error).splitlines()[0][:80]
                                     if str(error) else "")
    failures.append("binary PLY: meshio %s read it; update docs/volume-export.md" %
                    meshio.__version__)
    return "read"


def main():
    binary, ascii_ply, obj = sys.argv[1:4]
    vertices, faces = read_ply(binary)
    failures = []
    check_ascii_ply(ascii_ply, vertices, faces, failures)
    groups = check_obj(obj, vertices, faces, failures)
    binary_outcome = check_binary_ply(binary, failures)
    for line in failures[:10]:
        print("volume_meshio_check:", line)
    print("volume_meshio_check: %d faces; ascii PLY and OBJ (%d groups) read by meshio; "
          "binary PLY %s; %d failures" % (len(faces), groups, binary_outcome, len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
