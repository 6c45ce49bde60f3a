#!/usr/bin/env python3
"""Turns Google Benchmark JSON from umbra_render_bench into a Markdown table:
per mesh and light count, the median frame time with shadows and without,
their ratio, the shadows' cost per light in plain frames ((ratio - 1) /
lights), Williams' shadow maps (default settings) in the same run and their
ratio to plain, the shadowed frame's phases, samples and spans per second and
exact fallbacks per frame (pixels decided again in full, and (pixel,
light) counts recounted alone). A second table sets the volume method
beside Embree (issue 20): the ray method's frame and the volume frame's
ratio to it, umbra's visible-surface pass alone (the volume method on the
scene without lights) against Embree's primary rays (the ray method on
the same) and against a minimal float z-buffer (bench/zbuffer.h)."""
import json
import sys


def main(path):
    runs = json.load(open(path))["benchmarks"]
    median = {}
    for r in runs:
        if r.get("aggregate_name") not in (None, "median"):
            continue
        _, mesh, lights, mode = r["run_name"].split("/")[:4]
        median[(mesh, int(lights.split(":")[1]), mode)] = r
    print("| mesh | lights | shadows (ms) | plain (ms) | ratio | per light | maps (ms) | "
          "maps / plain | volumes / scanline / decide (ms) | samples/s | spans/s | "
          "shadow polygons | bands skipped | exact fallbacks | exact recounts |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for (mesh, lights, mode), r in sorted(median.items()):
        if mode != "shadows":
            continue
        plain = median.get((mesh, lights, "plain"))
        t = r["real_time"]
        tp = plain["real_time"] if plain else float("nan")
        maps = median.get((mesh, lights, "map"))
        tm = maps["real_time"] if maps else float("nan")
        phases = " / ".join(f"{r[k] * 1e3:.0f}" for k in ("s_volumes", "s_raster", "s_decide"))
        print(f"| {mesh} | {lights} | {t:.0f} | {tp:.0f} | {t / tp:.2f} | "
              f"{(t / tp - 1) / lights:.2f} | {tm:.0f} | {tm / tp:.2f} | {phases} | "
              f"{r['samples_per_s'] / 1e6:.1f} M | {r['spans_per_s'] / 1e3:.0f} k | "
              f"{r['shadow_polygons']:.0f} | {r['shadow_bands_skipped']:.0f} | "
              f"{r['exact_fallbacks']:.0f} | {r.get('exact_recounts', 0):.0f} |")

    def time(mesh, lights, mode):
        r = median.get((mesh, lights, mode))
        return r["real_time"] if r else float("nan")

    print()
    print("| mesh | lights | volume (ms) | Embree rays (ms) | volume / Embree | surface (ms) | "
          "Embree primary (ms) | surface / primary | z-buffer (ms) | surface / z-buffer |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for (mesh, lights, mode) in sorted(median):
        if mode != "shadows":
            continue
        t, ray = time(mesh, lights, "shadows"), time(mesh, lights, "ray")
        plain, primary = time(mesh, lights, "surface"), time(mesh, lights, "primary")
        z = time(mesh, lights, "zbuffer")
        print(f"| {mesh} | {lights} | {t:.0f} | {ray:.0f} | {t / ray:.2f} | {plain:.0f} | "
              f"{primary:.0f} | {plain / primary:.2f} | {z:.0f} | {plain / z:.2f} |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out/bench.json")
