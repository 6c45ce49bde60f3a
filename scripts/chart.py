#!/usr/bin/python3
"""Draws the speed/accuracy charts of umbra_chart's CSV (issue 5).

Usage: scripts/chart.py RESULTS.csv OUTDIR

Writes OUTDIR/chart-<scene>.png (time against error, one curve per method
and shadow-map setting), OUTDIR/sweep-<name>.png (false-lit and
false-shadowed samples against the swept parameter, one line per method) and
OUTDIR/summary.md (the headline numbers: volume against ray, and the shadow
map's error at the resolution whose time is nearest the volume method's).
"""
import csv
import sys
from collections import OrderedDict, defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {"volume": dict(color="black", marker="*", markersize=13),
         "ray": dict(color="tab:green", marker="o"),
         "map": dict(marker="s", markersize=4)}


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        r["median_ms"] = float(r["median_s"]) * 1e3
        r["scored"] = int(r["scored"])
        r["errors"] = int(r["errors"])
        for k in ("false_lit", "false_shadowed", "wrong_range"):
            r[k] = int(r[k])
        r["pct"] = 100.0 * r["errors"] / r["scored"] if r["scored"] else 0.0
        r["value"] = float(r["value"])
        # Area lights: the mean |V - V_exact| (absent in CSVs before it).
        soft = r.get("soft_mean_error") or ""
        r["soft_mean"] = float(soft) if soft else None
    return rows


def error_axis(ax, label):
    # Zero errors must show: linear up to 0.01 %, logarithmic above.
    ax.set_yscale("symlog", linthresh=0.01)
    ax.set_ylim(bottom=-0.002)
    ax.set_ylabel(label)
    ax.grid(True, which="both", alpha=0.3)


def scene_chart(name, rows, out):
    # A scene with area lights is judged by |V - V_exact|, not by classes.
    soft = any(r["soft_mean"] is not None for r in rows)
    fig, ax = plt.subplots(figsize=(7.5, 5))
    curves = OrderedDict()
    for r in rows:
        curves.setdefault(r["curve"], []).append(r)
    for curve, pts in curves.items():
        if pts[0]["method"] == "plain":
            ax.axvline(pts[0]["median_ms"], color="grey", linestyle="--", linewidth=1)
            ax.text(pts[0]["median_ms"], 0.98, " no shadows", color="grey", fontsize=8,
                    va="top", transform=ax.get_xaxis_transform())
            continue
        method = pts[0]["method"]
        if method == "map":
            pts.sort(key=lambda r: int(r["map_resolution"]))
        if soft and method == "ray":
            pts.sort(key=lambda r: int(r["ray_area_samples"]))
        xs = [p["median_ms"] for p in pts]
        # The volume's certified V errs by the float AOV's rounding (~1e-11
        # on average): drawn at 1e-12 and above.
        ys = [max(p["soft_mean"] or 0, 1e-12) if soft else p["pct"] for p in pts]
        style = dict(STYLE[method])
        if method == "map" and pts[0].get("map_variant") not in (None, "", "depth"):
            style["linestyle"] = "--"  # the source papers' variants (issue 22)
            if pts[0].get("map_variant") == "ikedo":
                style["marker"] = "^"  # Ikedo's penumbra, one curve per coefficient set
        ax.plot(xs, ys, label=curve, linewidth=1.2, **style)
        if soft and method in ("ray", "map"):
            for p, y in zip(pts, ys):
                label = p["ray_area_samples"] if method == "ray" else p["map_resolution"]
                ax.annotate(label, (p["median_ms"], y), fontsize=7, xytext=(3, 4),
                            textcoords="offset points")
        if not soft and method == "map" and "default bias" in curve and "nearest" in curve:
            for p in pts:
                ax.annotate(p["map_resolution"], (p["median_ms"], p["pct"]), fontsize=7,
                            xytext=(3, 4), textcoords="offset points")
    ax.set_xscale("log")
    ax.set_xlabel("frame time (ms, median)")
    if soft:
        ax.set_yscale("log")
        ax.set_ylabel("mean |V - V_exact| over scored samples")
        ax.grid(True, which="both", alpha=0.3)
    else:
        error_axis(ax, "misclassified samples (% of non-boundary)")
    first = rows[0]
    ax.set_title(f"{name}: {first['lights']} light(s), {first['width']}x{first['height']}")
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    fig.savefig(out / f"chart-{name}.png", dpi=110)
    plt.close(fig)


def sweep_chart(name, rows, out):
    fig, axes = plt.subplots(2, 1, figsize=(7.5, 6.5), sharex=True)
    curves = OrderedDict()
    for r in rows:
        curves.setdefault(r["curve"], []).append(r)
    log_axis = rows[0]["kind"] == "sweep-log"
    for curve, pts in curves.items():
        pts.sort(key=lambda r: r["value"])
        method = pts[0]["method"]
        style = dict(STYLE[method])
        if method == "map":
            style["linestyle"] = "-" if "default" in curve else ":"
        for ax, key in zip(axes, ("false_lit", "false_shadowed")):
            ys = [100.0 * p[key] / p["scored"] if p["scored"] else 0 for p in pts]
            ax.plot([p["value"] for p in pts], ys, label=curve, **style)
    if log_axis:
        nonzero = [abs(r["value"]) for r in rows if r["value"] != 0]
        for ax in axes:
            ax.set_xscale("symlog", linthresh=min(nonzero) if nonzero else 1)
    error_axis(axes[0], "false lit (% of samples)")
    error_axis(axes[1], "false shadowed (% of samples)")
    axes[1].set_xlabel(rows[0]["parameter"])
    axes[0].set_title(f"stability sweep: {name}")
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / f"sweep-{name}.png", dpi=110)
    plt.close(fig)


VARIANTS = (("depth", "nearest, default bias"), ("post", "post-process"),
            ("id", "ID buffer per object"), ("id-polygon", "ID buffer per polygon"))


def variant_table(scenes):
    """The source papers' map variants side by side (issue 22): errors as
    false-lit / false-shadowed at the largest resolution each scene ran."""
    lines = ["", "## Shadow-map variants: errors (false-lit / false-shadowed)", "",
             "| scene | resolution | " + " | ".join(n for _, n in VARIANTS) + " |",
             "| --- | --- |" + " --- |" * len(VARIANTS)]
    for name, rows in scenes.items():
        maps = [r for r in rows if r["method"] == "map" and r.get("map_variant")]
        if not any(r["map_variant"] != "depth" for r in maps):
            continue
        res = max(int(r["map_resolution"]) for r in maps)
        cells = [name, str(res)]
        for variant, curve in VARIANTS:
            hit = [r for r in maps if r["map_variant"] == variant and
                   int(r["map_resolution"]) == res and curve in r["curve"]]
            cells.append(f"{hit[0]['false_lit']} / {hit[0]['false_shadowed']} "
                         f"({hit[0]['median_ms']:.1f} ms)" if hit else "–")
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def summary(scenes, sweeps, out):
    lines = ["# Speed against accuracy: headline numbers", "",
             "| scene | volume ms (errors) | ray ms (errors) | volume / ray time | "
             "map at the volume's time: resolution, ms, errors | no-shadow ms |",
             "| --- | --- | --- | --- | --- | --- |"]
    for name, rows in scenes.items():
        get = {r["method"]: r for r in rows if r["method"] in ("volume", "plain")}
        # The default epsilon is the middle of the ray curve's points.
        rays = sorted((r for r in rows if r["method"] == "ray"),
                      key=lambda r: float(r["ray_epsilon"]))
        ray = rays[len(rays) // 2] if rays else None
        maps = [r for r in rows if r["method"] == "map" and "nearest, default bias" in r["curve"]]
        vol, plain = get.get("volume"), get.get("plain")
        if not vol:
            continue
        cells = [name, f"{vol['median_ms']:.1f} ({vol['errors']} of {vol['scored']})"]
        cells.append(f"{ray['median_ms']:.1f} ({ray['errors']})" if ray else "–")
        cells.append(f"{vol['median_ms'] / ray['median_ms']:.2f}" if ray else "–")
        if maps:
            m = min(maps, key=lambda r: abs(r["median_ms"] - vol["median_ms"]))
            cells.append(f"{m['map_resolution']}, {m['median_ms']:.1f}, {m['errors']} "
                         f"({m['pct']:.3f} %: {m['false_lit']} false-lit, "
                         f"{m['false_shadowed']} false-shadowed)")
        else:
            cells.append("–")
        cells.append(f"{plain['median_ms']:.1f}" if plain else "–")
        lines.append("| " + " | ".join(cells) + " |")
    lines += variant_table(scenes)
    lines += ["", "## Sweeps: errors (false-lit / false-shadowed) per point", ""]
    for name, rows in sweeps.items():
        curves = OrderedDict()
        for r in rows:
            curves.setdefault(r["curve"], {})[r["value"]] = r
        values = sorted({r["value"] for r in rows})
        lines.append(f"### {name} ({rows[0]['parameter']})")
        lines.append("")
        lines.append("| method | " + " | ".join(f"{v:g}" for v in values) + " |")
        lines.append("| --- |" + " --- |" * len(values))
        for curve, by_value in curves.items():
            cells = []
            for v in values:
                r = by_value.get(v)
                cells.append(f"{r['false_lit']}/{r['false_shadowed']}" if r else "–")
            lines.append(f"| {curve} | " + " | ".join(cells) + " |")
        lines.append("")
    (out / "summary.md").write_text("\n".join(lines) + "\n")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    rows = load(sys.argv[1])
    out = Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    scenes, sweeps = OrderedDict(), OrderedDict()
    for r in rows:
        (scenes if r["kind"] == "scene" else sweeps).setdefault(r["name"], []).append(r)
    for name, rs in scenes.items():
        scene_chart(name, rs, out)
    for name, rs in sweeps.items():
        sweep_chart(name, rs, out)
    summary(scenes, sweeps, out)
    print(f"chart.py: {len(scenes)} scene charts, {len(sweeps)} sweep charts, summary.md in {out}")


if __name__ == "__main__":
    main()
