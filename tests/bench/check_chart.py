#!/usr/bin/python3
"""CTest check of a quick umbra_chart run: the CSV holds every method on every
chart scene and every sweep point, the volume method never misclassifies a
sample (nor errs by more than 1e-6 in an area light's V), each scored row
scored samples, and chart.py drew every chart.

Usage: check_chart.py RESULTS.csv CHART_DIR
"""
import csv
import sys
from pathlib import Path

SWEEPS = {"grazing", "light_near_plane", "scale", "far_from_origin", "perturbed", "eye_into_volume",
          "light_in_view"}


def fail(message):
    sys.exit(f"check_chart: {message}")


def main():
    rows = list(csv.DictReader(open(sys.argv[1], newline="")))
    out = Path(sys.argv[2])
    if not rows:
        fail("no rows")
    by_name = {}
    for r in rows:
        by_name.setdefault((r["kind"], r["name"]), set()).add(r["method"])
        if r["method"] == "plain":
            continue
        if int(r["scored"]) <= 0:
            fail(f"{r['name']} {r['curve']}: nothing scored")
        if r["method"] == "volume" and int(r["errors"]) != 0:
            fail(f"volume misclassified {r['errors']} samples on {r['name']} {r['value']}")
        if float(r["median_s"]) <= 0:
            fail(f"{r['name']} {r['curve']}: no time")
        if r["name"].startswith("soft"):
            # An area light's rows carry |V - V_exact|; the volume's within 1e-6.
            if not r["soft_mean_error"] or not r["soft_max_error"]:
                fail(f"{r['name']} {r['curve']}: no visible-fraction error")
            if r["method"] == "volume" and float(r["soft_max_error"]) > 1e-6:
                fail(f"volume's V errs by {r['soft_max_error']} on {r['name']}")
        if r["name"] == "coloured":
            # Coloured shadows carry per-channel τ errors; the volume's none.
            if not r["tau_mismatches"] or not r["tau_max_error"]:
                fail(f"coloured {r['curve']}: no transmittance error")
            if r["method"] == "volume" and float(r["tau_max_error"]) > 1e-6:
                fail(f"volume's τ errs by {r['tau_max_error']} on coloured")
    scenes = {n for (k, n) in by_name if k == "scene"}
    sweeps = {n for (k, n) in by_name if k != "scene"}
    if sweeps != SWEEPS:
        fail(f"sweeps {sorted(sweeps)} instead of {sorted(SWEEPS)}")
    for (kind, name), methods in by_name.items():
        wanted = {"plain", "volume", "map", "ray"} if kind == "scene" else {"volume", "map", "ray"}
        if methods != wanted:
            fail(f"{name}: methods {sorted(methods)} instead of {sorted(wanted)}")
    for name in scenes:
        if not (out / f"chart-{name}.png").stat().st_size:
            fail(f"chart-{name}.png is empty")
    for name in sweeps:
        if not (out / f"sweep-{name}.png").stat().st_size:
            fail(f"sweep-{name}.png is empty")
    # The source papers' map variants (issue 22) on every hard-light scene.
    for name in scenes:
        if name.startswith("soft"):
            continue
        variants = {r.get("map_variant") for r in rows
                    if r["name"] == name and r["method"] == "map"}
        if not {"depth", "post", "id"} <= variants:
            fail(f"{name}: map variants {sorted(v for v in variants if v)}")
    if "Shadow-map variants" not in (out / "summary.md").read_text():
        fail("summary.md lacks the map variants' table")
    if "soft" not in scenes:
        fail("no area-light scene")
    # Ikedo's penumbra beside PCSS on every area-light scene.
    for name in scenes:
        if name.startswith("soft") and not any(
                r.get("map_variant") == "ikedo" for r in rows if r["name"] == name):
            fail(f"{name}: no Ikedo penumbra row")
    if "coloured" not in scenes:
        fail("no scene with transmittance")
    if "| default |" not in (out / "summary.md").read_text():
        fail("summary.md lacks the default scene")
    print(f"check_chart: {len(rows)} rows, {len(scenes)} scenes, {len(sweeps)} sweeps: ok")


if __name__ == "__main__":
    main()
