#!/usr/bin/env python3
"""A JUnit report of `umbra fuzz check|real|merge --junit` read back with
xml.etree, independently of umbra's writer, against the JSON summary of the
same run: one testcase per scene with the scene's name, counts that agree,
a <failure> (mismatch) or <error> (refused) under every failing scene whose
message is the summary's verdict, and nothing under the others.
Usage: fuzz_junit_check.py SUMMARY.json REPORT.xml   (exit 0 or 1 with a reason)
"""
import json
import sys
import xml.etree.ElementTree as ET

summary = json.load(open(sys.argv[1], encoding="utf-8"))
root = ET.parse(sys.argv[2]).getroot()
suites = root.findall("testsuite")
assert root.tag == "testsuites" and len(suites) == 1, "one testsuite under testsuites"
suite = suites[0]
cases = suite.findall("testcase")
seed = summary["seed"]
if summary["verb"] == "check":
    shard, shards = summary["shard"]
    indices = [summary["index"]] if summary["index"] is not None else \
        range(shard, summary["count"], shards)
    names = [f"s{seed}-{i}" for i in indices]
else:
    names = [f"{m['name']}-s{seed}-{i}" for m in summary["mesh_scenes"]
             for i in range(m["first"], m["first"] + m["scenes"])]
failures = {f["name"]: f for f in summary["failures"]}
errors = sum(1 for f in summary["failures"] if f["refused"])
for element in (root, suite):
    got = {k: int(element.get(k)) for k in ("tests", "failures", "errors")}
    want = {"tests": summary["scenes"], "failures": summary["failed"] - errors, "errors": errors}
    assert got == want, f"{element.tag} counts {got}, the summary says {want}"
assert [c.get("name") for c in cases] == names, "testcase names are not the scenes in order"
for case in cases:
    verdicts = case.findall("failure") + case.findall("error")
    f = failures.get(case.get("name"))
    if f is None:
        assert not verdicts, f"{case.get('name')} passed but has {verdicts[0].tag}"
        continue
    assert len(verdicts) == 1, f"{case.get('name')} failed: one failure or error expected"
    tag = "error" if f["refused"] else "failure"
    assert verdicts[0].tag == tag, f"{case.get('name')}: <{verdicts[0].tag}>, expected <{tag}>"
    assert verdicts[0].get("message") == f["what"], f"{case.get('name')}: message differs"
    assert f["recipe"] in verdicts[0].text, f"{case.get('name')}: no recipe in the text"
print(f"{sys.argv[2]}: {len(cases)} testcases, {len(failures)} failing, as {sys.argv[1]} says")
