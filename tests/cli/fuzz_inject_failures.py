#!/usr/bin/env python3
"""Adds failing scenes to `umbra fuzz check` summaries, as the run writes
them, so that the shard test can show failures and refusals merge in the
one-process order (a run of the generator that fails cannot be counted on).
Usage: fuzz_inject_failures.py FILE.json INDEX:refused|mismatch ...
Each FILE gets the failures whose index is of its shard, in index order.
"""
import json
import sys

path, specs = sys.argv[1], sys.argv[2:]
summary = json.load(open(path, encoding="utf-8"))
shard, shards = summary["shard"]
seed = summary["seed"]
for spec in sorted(specs, key=lambda s: int(s.split(":")[0])):
    index, kind = int(spec.split(":")[0]), spec.split(":")[1]
    if index % shards != shard:
        continue
    refused = kind == "refused"
    summary["failed"] += 1
    summary["refused"] += int(refused)
    for feature in ("cube", "light_on_vertex"):  # keys some parts lack: merged as a union
        counts = summary["failing_features"]
        counts[feature] = counts.get(feature, 0) + 1
    summary["failing_features"] = dict(sorted(summary["failing_features"].items()))
    summary["failures"].append({
        "index": index, "name": f"s{seed}-{index}",
        "recipe": f"umbra fuzz export DIR --seed {seed} --index {index}",
        "what": "refused: shadow volume count -1 for light 0" if refused
        else "closed; 3 mismatches",
        "refused": refused, "mismatches": 0 if refused else 3,
        "features": ["cube", "light_on_vertex"], "lights": ["light_on_vertex"],
        "light_mismatches": [] if refused else [3],
        "failing_lights": "light 0 light_on_vertex: " + ("refused" if refused else "3 wrong")})
summary["failures"].sort(key=lambda f: f["index"])
json.dump(summary, open(path, "w", encoding="utf-8"), indent=2)
