#!/usr/bin/env python3
"""No source file over 500 lines without a reason in its first comment
(CONTRIBUTING.md): a long file usually holds two jobs. The reason is a
comment line in the file's opening comment block that says "over 500 lines".
Usage: check_file_sizes.py SOURCE_DIR   (exit 0 clean, 1 with the offenders)
"""
import pathlib
import sys

ROOT = pathlib.Path(sys.argv[1]).resolve()
LIMIT = 500
offenders = []
files = [p for folder in ("util", "geometry", "raster", "cli", "fuzz", "bench", "tests")
         for p in (ROOT / folder).rglob("*") if p.suffix in (".h", ".cpp")
         and "data" not in p.relative_to(ROOT).parts]
for path in sorted(files):
    lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
    if len(lines) <= LIMIT:
        continue
    opening = []
    for line in lines:
        if line.startswith("//") or line.startswith("#pragma"):
            opening.append(line)
        else:
            break
    if not any("over 500 lines" in line.lower() for line in opening):
        offenders.append(f"{path.relative_to(ROOT)}: {len(lines)} lines, no reason in its first comment")
for o in offenders:
    print(o)
print(f"check_file_sizes: {len(files)} files, {len(offenders)} over {LIMIT} lines without a reason")
sys.exit(1 if offenders else 0)
