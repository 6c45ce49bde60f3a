"""`import umbra` against umbra's own truth: every pixel of a volume render
is the exact oracle's class, the shadow volumes are the CLI's, and errors
are Python exceptions carrying umbra's one-line message (docs/python.md).
Run by CTest `python.module` with PYTHONPATH=build/python."""
import csv
import json
import os
import re
import subprocess

import numpy as np
import pytest

import umbra

DATA = os.environ["UMBRA_DATA"]  # the source tree's data/
CLI = os.environ["UMBRA_CLI"]  # build/cli/umbra

# shadow.<i> values (raster/frame.h) of the oracle's classes 0 lit,
# 1 shadowed, 2 out of range.
SHADOW_VALUE = np.array([1.0, 0.0, 0.5], dtype=np.float32)


def scene(name, camera=True):
    return umbra.load_scene(os.path.join(DATA, "scenes", name), camera=camera)


@pytest.mark.parametrize("name", ["two_lights.json", "degenerate.json", "closed.json"])
def test_every_pixel_of_a_volume_render_is_the_oracles_class(name):
    s = scene(name)
    width, height = s.size
    frame = s.render(method="volume", threads=2)
    assert frame["beauty"].shape == (height, width, 3)
    assert frame["beauty"].dtype == np.float32
    rays = s.sample_rays()
    origins = rays["origins"].reshape(-1, 3)
    directions = rays["directions"].reshape(-1, 3)
    classes = set()
    for light in range(s.lights):
        truth = s.in_shadow(origins, directions, light)
        shadow = frame[f"shadow.{light}"].reshape(-1)
        hit = truth["cls"] >= 0
        decided = hit & ~truth["boundary"]
        assert np.array_equal(shadow[decided], SHADOW_VALUE[truth["cls"][decided]])
        assert np.all(shadow[~hit] == 1.0)  # background: lit, as the EXR says
        assert np.all(np.isinf(frame["depth"].reshape(-1)[~hit]))
        assert decided.sum() > 0.3 * width * height
        classes |= set(np.unique(truth["cls"][decided]).tolist())
    # Each scene has lit and shadowed samples decided, so the comparison
    # cannot pass vacuously.
    assert {0, 1} <= classes


def test_the_shadow_volumes_are_the_ones_umbra_volume_exports(tmp_path):
    path = os.path.join(DATA, "scenes", "two_lights.json")
    out = subprocess.run([CLI, "volume", path, "-o", str(tmp_path / "v.ply")],
                         check=True, capture_output=True, text=True).stdout
    # "wrote v.ply: 97 faces (type 1: 12, type 2: 37, type 3: 48), ..."
    counts = re.search(r": (\d+) faces \(type 1: (\d+), type 2: (\d+), type 3: (\d+)", out)
    assert counts, out
    v = scene("two_lights.json").shadow_volumes()
    faces = len(v["type"])
    assert faces == int(counts[1])
    for t in (1, 2, 3):
        assert np.count_nonzero(v["type"] == t) == int(counts[t + 1])
    assert v["offsets"][0] == 0 and v["offsets"][-1] == len(v["vertices"])
    assert np.all(np.diff(v["offsets"]) >= 3)
    assert np.all(np.isfinite(v["vertices"]))
    # One light's polygons are the whole set's with that light.
    one = scene("two_lights.json").shadow_volumes(light=1)
    assert len(one["type"]) == np.count_nonzero(v["light"] == 1) > 0
    # Without caps, sides only (the renderer's volumes).
    sides = scene("two_lights.json").shadow_volumes(caps=False)
    assert set(np.unique(sides["type"])) <= {2}


def test_errors_are_python_exceptions_with_umbras_message(tmp_path):
    broken = tmp_path / "broken.json"
    broken.write_text("{\n")
    with pytest.raises(umbra.InputError) as e:
        umbra.load_scene(str(broken))
    assert str(e.value).startswith(str(broken) + ":2:1: malformed JSON")
    assert "\n" not in str(e.value)
    assert issubclass(umbra.InputError, ValueError)
    with pytest.raises(umbra.InputError):
        umbra.load_scene(str(tmp_path / "missing.json"))
    s = scene("two_lights.json")
    with pytest.raises(IndexError):
        s.in_shadow(np.zeros((1, 3)), np.ones((1, 3)), 2)
    with pytest.raises(ValueError, match=r"\(N, 3\)"):
        s.in_shadow(np.zeros((2, 3)), np.ones((3, 3)), 0)
    with pytest.raises(ValueError, match="zero"):
        s.in_shadow(np.zeros((1, 3)), np.zeros((1, 3)), 0)
    with pytest.raises(ValueError, match="method 'bogus'"):
        s.render(method="bogus")


def test_a_scene_without_a_camera_builds_volumes_but_does_not_render(tmp_path):
    path = tmp_path / "no_camera.json"
    with open(os.path.join(DATA, "scenes", "open.json")) as f:
        doc = json.load(f)
    del doc["camera"]
    for m in doc["models"]:
        if "mesh" in m:
            m["mesh"] = os.path.join(DATA, "scenes", m["mesh"])
    path.write_text(json.dumps(doc))
    s = umbra.load_scene(str(path))
    assert s.size is None
    assert len(s.shadow_volumes()["type"]) > 0
    with pytest.raises(umbra.InputError, match="has no camera"):
        s.render()
    with pytest.raises(umbra.InputError):
        umbra.load_scene(str(path), camera=True)


def test_footprints_are_the_ones_umbra_footprint_writes(tmp_path):
    path = os.path.join(DATA, "scenes", "sun", "golden.json")
    table = tmp_path / "f.csv"
    out = subprocess.run([CLI, "footprint", path, "-o", str(tmp_path / "f.ply"), "--csv",
                          str(table)], check=True, capture_output=True, text=True).stdout
    regions = int(re.search(r": (\d+) regions on", out)[1])
    f = umbra.load_scene(path).footprints()
    r = f["regions"]
    assert len(r["area"]) == regions > 0
    assert set(np.unique(r["cls"]).tolist()) == {0, 1}
    assert r["offsets"][-1] == len(r["vertices"])
    with open(table, newline="") as t:
        rows = list(csv.DictReader(t))
    s = f["receivers"]
    assert len(rows) == len(s["area"])
    for k, row in enumerate(rows):
        # The CSV's numbers are the shortest text of the same doubles.
        for key in ("area", "lit_area", "shadowed_area", "sunlit_fraction"):
            assert s[key][k] == float(row[key]), (k, key)
        for key in ("light", "model", "polygon", "facing"):
            assert s[key][k] == int(row[key]), (k, key)
    # Each receiver's regions of each class add up to its areas (rounded
    # exact values, so to a relative 1e-12).
    for k in range(len(rows)):
        mine = (r["light"] == s["light"][k]) & (r["model"] == s["model"][k]) & \
            (r["polygon"] == s["polygon"][k])
        assert np.isclose(r["area"][mine & (r["cls"] == 1)].sum(), s["lit_area"][k],
                          rtol=1e-12, atol=1e-9)
    one = umbra.load_scene(path).footprints(lights=[1])
    assert set(one["regions"]["light"].tolist()) == {1}
    with pytest.raises(ValueError, match="light"):
        umbra.load_scene(path).footprints(lights=[7])
