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
the same) and against a minimal float z-buffer (bench/zbuffer.h). A third
sets the tinted twin (coloured shadows) beside the opaque frame. A fourth,
when the run has the night city (UMBRA_BENCH_CITY), sets its many-lamp
frames beside the one-lamp frame, the plain pass and Embree."""
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
        if mode != "shadows" or mesh == "city":
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
        if mode != "shadows" or mesh == "city":
            continue
        t, ray = time(mesh, lights, "shadows"), time(mesh, lights, "ray")
        plain, primary = time(mesh, lights, "surface"), time(mesh, lights, "primary")
        z = time(mesh, lights, "zbuffer")
        print(f"| {mesh} | {lights} | {t:.0f} | {ray:.0f} | {t / ray:.2f} | {plain:.0f} | "
              f"{primary:.0f} | {plain / primary:.2f} | {z:.0f} | {plain / z:.2f} |")

    tinted = [(mesh, lights) for (mesh, lights, mode) in sorted(median) if mode == "tinted"]
    if tinted:
        # Coloured shadows (issue 22): the same scene with both models
        # tinted against it opaque, in the same run.
        print()
        print("| mesh | lights | opaque (ms) | tinted (ms) | tinted / opaque |")
        print("| --- | --- | --- | --- | --- |")
        for mesh, lights in tinted:
            t, c = time(mesh, lights, "shadows"), time(mesh, lights, "tinted")
            print(f"| {mesh} | {lights} | {t:.0f} | {c:.0f} | {c / t:.2f} |")

    city = sorted(lights for (mesh, lights, mode) in median if mesh == "city" and mode == "shadows")
    if city:
        # Many lights (issue 20, goal 4): the frame against the one-lamp
        # frame, its plain pass and Embree, and the (pixel, light) pairs kept.
        one = time("city", city[0], "shadows")
        print()
        print("| city lamps | volume (ms) | plain (ms) | volume / plain | volume / 1 lamp | "
              "Embree rays (ms) | volume / Embree | light pixels | light pixels / pixel |")
        print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
        for lights in city:
            r = median[("city", lights, "shadows")]
            t, plain, ray = r["real_time"], time("city", lights, "plain"), time("city", lights, "ray")
            kept = r.get("light_pixels", float("nan"))
            print(f"| {lights} | {t:.0f} | {plain:.0f} | {t / plain:.2f} | {t / one:.2f} | "
                  f"{ray:.0f} | {t / ray:.2f} | {kept:.0f} | {kept / (1280 * 720):.2f} |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out/bench.json")
