#!/usr/bin/env python3
"""Reads what `umbra footprint --sun-times` wrote, independently of umbra,
and checks the files against each other and against EnergyPlus's
Schedule:File:Shading layout (docs/sun.md "Time series"):

- the schedule: a header `Surface Name,<one column per surface>` with
  distinct names, ROWS rows labelled `MM/DD HH:MM` STEP apart, every value a
  number in [0, 1];
- every row of the per-step CSV has the same sunlit fraction, to the bit, in
  the schedule's row of its time and the column of its surface (a model's
  name when it has one polygon, else name:polygon, then :type for a named
  polygon); schedule rows of steps
  the CSV lacks (the sun down) are all 0;
- with a sun-hours PLY: per receiver polygon the regions' areas (Newell's
  formula on the file's doubles) add up to its area; sun_hours is
  lit_steps x STEP; lit_runs <= lit_steps; and the regions' area x
  lit_steps, summed, equals the CSV's front lit areas summed over the steps
  (sun hours integrate the steps' footprints).
Usage: sun_series_check.py SCHEDULE.csv STEPS.csv STEP_SECONDS ROWS [HOURS.ply]
"""
import csv
import datetime
import os
import re
import sys
from collections import defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from footprint_check import area, read_ply  # noqa: E402


def main():
    schedule_path, steps_path, step, rows_expected = sys.argv[1:5]
    step, rows_expected = float(step), int(rows_expected)
    failures = []
    table = list(csv.reader(open(schedule_path, newline="")))
    header, body = table[0], table[1:]
    if header[0] != "Surface Name":
        failures.append("first header cell %r, not 'Surface Name'" % header[0])
    names = header[1:]
    if len(set(names)) != len(names):
        failures.append("duplicate surface names")
    if len(body) != rows_expected:
        failures.append("%d rows, expected %d" % (len(body), rows_expected))
    label = re.compile(r"^(\d\d)/(\d\d) (\d\d):(\d\d)$")
    first = None
    for k, row in enumerate(body):
        m = label.match(row[0])
        if not m or len(row) != len(header):
            failures.append("row %d: %r" % (k, row[:2]))
            continue
        month, day, hour, minute = map(int, m.groups())
        when = datetime.datetime(2001, month, day, hour, minute)  # any non-leap year
        if first is None:
            first = when
        expected = first + datetime.timedelta(seconds=k * step)
        if (expected.month, expected.day, expected.hour, expected.minute) != (
                month, day, hour, minute):
            failures.append("row %d labelled %s, expected %s" % (k, row[0], expected))
        for v in row[1:]:
            if not 0 <= float(v) <= 1:
                failures.append("row %d: value %s outside [0, 1]" % (k, v))
    by_label = {}
    for k, row in enumerate(body):
        by_label.setdefault(row[0], k)

    steps = list(csv.DictReader(open(steps_path, newline="")))
    polygons = defaultdict(set)
    for r in steps:
        polygons[r["model"]].add(r["polygon"])
    seen_rows = set()
    front_lit = defaultdict(float)
    receiver_area = {}
    for r in steps:
        t = datetime.datetime.fromisoformat(r["time"])
        k = by_label.get(t.strftime("%m/%d %H:%M"))
        name = r["model_name"] if len(polygons[r["model"]]) == 1 else "%s:%s" % (
            r["model_name"], r["polygon"])
        if r.get("polygon_name"):  # a CityJSON surface's type
            name += ":" + r["polygon_name"]
        if k is None or name not in names:
            failures.append("no schedule cell for %s %s" % (r["time"], name))
            continue
        seen_rows.add(k)
        cell = body[k][1 + names.index(name)]
        if float(cell) != float(r["sunlit_fraction"]):
            failures.append("%s %s: schedule %s, steps %s" % (r["time"], name, cell,
                                                                r["sunlit_fraction"]))
        key = (int(r["model"]), int(r["polygon"]))
        receiver_area[key] = float(r["area"])
        if int(r["facing"]) > 0:
            front_lit[key] += float(r["lit_area"])
    for k, row in enumerate(body):
        if k not in seen_rows and any(float(v) != 0 for v in row[1:]):
            failures.append("row %d (%s): the sun is down but a value is not 0" % (k, row[0]))

    if len(sys.argv) > 5:
        vertices, faces = read_ply(sys.argv[5])
        sums = defaultdict(float)
        integral = defaultdict(float)
        daylight = len({r["time"] for r in steps})
        for i, f in enumerate(faces):
            a = area([vertices[j] for j in f["vertex_indices"]])
            key = (f["model"], f["polygon"])
            sums[key] += a
            integral[key] += a * f["lit_steps"]
            if f["sun_hours"] != f["lit_steps"] * step / 3600:
                failures.append("face %d: sun_hours %r for %d steps" % (i, f["sun_hours"],
                                                                         f["lit_steps"]))
            if not f["lit_runs"] <= f["lit_steps"] <= daylight:
                failures.append("face %d: %d runs of %d steps" % (i, f["lit_runs"],
                                                                   f["lit_steps"]))
        for key, total in receiver_area.items():
            if abs(sums[key] - total) > 1e-9 * max(1.0, total):
                failures.append("receiver %s: regions add up to %r, not %r" % (key, sums[key],
                                                                              total))
            if abs(integral[key] - front_lit[key]) > 1e-9 * max(1.0, total) * daylight:
                failures.append("receiver %s: area x lit steps %r, steps' lit areas %r" % (
                    key, integral[key], front_lit[key]))
        print("%d sun-hours regions" % len(faces))
    for f in failures[:20]:
        print(f)
    print("%d rows, %d surfaces, %d step rows: %d failures" % (len(body), len(names), len(steps),
                                                                len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
