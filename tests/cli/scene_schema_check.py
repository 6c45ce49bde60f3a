#!/usr/bin/python3
"""docs/scene.schema.json against umbra's loader (CTest scene_schema):

- the schema is a valid JSON Schema (draft 2020-12, Debian's
  python3-jsonschema);
- every JSON scene under data/scenes (CityJSON files aside) and
  tests/data/scenes/full.json satisfies it, and umbra loads each
  (`umbra volume`, which needs no camera);
- every scene in tests/data/scenes/schema_bad breaks it, and umbra refuses
  each (exit 2): the schema is never stricter than the loader on them.
Usage: scene_schema_check.py UMBRA REPO_DIR WORK_DIR
"""
import glob
import json
import os
import subprocess
import sys

import jsonschema

umbra, repo, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
schema = json.load(open(os.path.join(repo, "docs", "scene.schema.json")))
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)


def umbra_exit(scene):
    out = os.path.join(work, "volume.ply")
    return subprocess.run([umbra, "volume", scene, "-o", out, "-q"],
                          capture_output=True).returncode


good = [p for p in glob.glob(os.path.join(repo, "data", "scenes", "**", "*.json"), recursive=True)
        if not p.endswith(".city.json")]
good.append(os.path.join(repo, "tests", "data", "scenes", "full.json"))
bad = sorted(glob.glob(os.path.join(repo, "tests", "data", "scenes", "schema_bad", "*.json")))
failures = []
for path in sorted(good):
    errors = list(validator.iter_errors(json.load(open(path))))
    if errors:
        failures.append("%s: the schema refuses a good scene: %s" % (path, errors[0].message))
    if umbra_exit(path) != 0:
        failures.append("%s: umbra does not load it" % path)
for path in bad:
    if validator.is_valid(json.load(open(path))):
        failures.append("%s: the schema accepts a bad scene" % path)
    if umbra_exit(path) != 2:
        failures.append("%s: umbra does not refuse it with exit 2" % path)
for f in failures:
    print(f)
print("scene schema: %d good scenes, %d bad ones, %d failures" % (len(good), len(bad),
                                                                 len(failures)))
sys.exit(1 if failures or len(good) < 20 or len(bad) < 10 else 0)
