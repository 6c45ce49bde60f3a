#!/usr/bin/env python3
"""What may include what (docs/architecture.md), checked on the source tree.

Follows umbra's own includes transitively (`#include <folder/...>` rooted at
the project; the libraries' headers by their installed names,
`<umbra/geometry/...>`) and fails, naming the chain, when a rule is broken:
- the libraries (util/, geometry/, raster/) are included as <umbra/...>
  everywhere, never by their bare folder (that only resolves in this tree);
- util/ includes nothing of umbra's but util/;
- geometry/ never reaches raster/, cli/, fuzz/ or bench/;
- raster/ never reaches a CGAL or OpenMesh header (it gets plain values and
  exact decisions from geometry/), nor cli/, fuzz/, bench/;
- the `umbra` executable's sources (cli/) never reach fuzz/ or bench/;
- the Python module (python/) never reaches cli/, fuzz/ or bench/: like the
  CLI, a thin layer over the libraries;
- OpenImageIO is included by raster/image_codec_oiio.cpp alone (the module
  kept as the tests' independent reader), OpenEXR by raster/exr_encode.cpp,
  exr_decode.cpp and openexr_support.h alone, libpng and zlib by
  raster/png_encode.cpp alone, Embree by
  raster/methods/ alone, tinygltf by geometry/io/ alone, simdjson by
  geometry/io/json_document.h alone, PROJ by geometry/export/geodetic_frame.cpp
  alone, pybind11 by python/ alone, mimalloc by cli/heap.cpp alone (the
  program's allocator; the libraries keep the system's).
- cmake/internal-headers.txt lists exactly the libraries' headers that reach
  a private dependency (CGAL, GMP, OpenMesh, fmt, ...): those are not
  installed, every other header is (cmake/umbra_install.cmake).
Usage: check_includes.py SOURCE_DIR   (exit 0 clean, 1 with the violations)
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(sys.argv[1]).resolve()
PROJECT = ("util", "geometry", "raster", "cli", "fuzz", "bench", "tests", "python")
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)


LIBRARIES = ("util", "geometry", "raster")


def project_name(inc):
    """umbra/geometry/x.h -> geometry/x.h: where the header lives in the tree."""
    parts = inc.split("/")
    if len(parts) > 2 and parts[0] == "umbra" and parts[1] in LIBRARIES:
        return "/".join(parts[1:])
    return inc


def raw_includes(path):
    return INCLUDE.findall(path.read_text(encoding="utf-8", errors="replace"))


def includes(path):
    return [project_name(inc) for inc in raw_includes(path)]


def reach(start):
    """Every include reachable from `start`: {include: chain of files}."""
    seen = {}
    stack = [(start, [str(start.relative_to(ROOT))])]
    while stack:
        path, chain = stack.pop()
        for inc in includes(path):
            if inc in seen:
                continue
            seen[inc] = chain + [inc]
            if inc.split("/")[0] in PROJECT and (ROOT / inc).is_file():
                stack.append((ROOT / inc, chain + [inc]))
    return seen


def sources(folder):
    return sorted(p for p in (ROOT / folder).rglob("*") if p.suffix in (".h", ".cpp"))


RULES = [
    ("util", lambda inc: inc.split("/")[0] in PROJECT and not inc.startswith("util/"),
     "util/ includes only util/"),
    ("geometry", lambda inc: inc.split("/")[0] in ("raster", "cli", "fuzz", "bench"),
     "geometry/ never includes raster/, cli/, fuzz/ or bench/"),
    ("raster", lambda inc: inc.startswith(("CGAL/", "OpenMesh/")),
     "raster/ never includes CGAL or OpenMesh"),
    ("raster", lambda inc: inc.split("/")[0] in ("cli", "fuzz", "bench"),
     "raster/ never includes cli/, fuzz/ or bench/"),
    ("cli", lambda inc: inc.split("/")[0] in ("fuzz", "bench"),
     "the umbra executable (cli/) never includes fuzz/ or bench/"),
    ("python", lambda inc: inc.split("/")[0] in ("cli", "fuzz", "bench"),
     "the Python module (python/) never includes cli/, fuzz/ or bench/"),
]
ONLY_IN = [
    ("OpenImageIO/", ("raster/image_codec_oiio.cpp",)),
    ("OpenEXR/", ("raster/exr_encode.cpp", "raster/exr_decode.cpp", "raster/openexr_support.h")),
    ("Imath/", ("raster/exr_encode.cpp", "raster/exr_decode.cpp")),
    ("png.h", ("raster/png_encode.cpp",)),
    ("zlib.h", ("raster/png_encode.cpp",)),
    ("embree3/", ("raster/methods/",)),
    ("tiny_gltf.h", ("geometry/io/",)),
    ("simdjson.h", ("geometry/io/json_document.h",)),
    ("proj.h", ("geometry/export/geodetic_frame.cpp",)),
    ("proj/", ("geometry/export/geodetic_frame.cpp",)),
    ("pybind11/", ("python/",)),
    ("mimalloc", ("cli/heap.cpp",)),
]

violations = []
for folder in PROJECT:
    for src in sources(folder):
        for inc in raw_includes(src):
            if inc.split("/")[0] in LIBRARIES:
                violations.append(f"include umbra's libraries as <umbra/{inc}>: "
                                  f"{src.relative_to(ROOT)}")
for folder, bad, rule in RULES:
    for src in sources(folder):
        for inc, chain in reach(src).items():
            if bad(inc):
                violations.append(f"{rule}: {' -> '.join(chain)}")
for folder in ("util", "geometry", "raster", "cli", "python"):
    for src in sources(folder):
        rel = str(src.relative_to(ROOT))
        for inc in includes(src):
            for prefix, allowed in ONLY_IN:
                if inc.startswith(prefix) and not rel.startswith(allowed):
                    violations.append(f"{prefix} only in {', '.join(allowed)}: {rel}")

# Installed headers reach only the standard library, the system, TBB and
# other installed headers.
PRIVATE_DEPENDENCIES = ("CGAL/", "OpenMesh/", "embree3/", "glm/", "fmt/", "nlohmann/", "simdjson",
                        "tiny_gltf", "proj", "gmp", "OpenImageIO/", "CLI/", "boost/", "pybind11/",
                        "OpenEXR/", "Imath/", "png.h", "zlib.h")
reaching = set()
for folder in LIBRARIES:
    for src in sources(folder):
        if src.suffix == ".h" and any(inc.startswith(PRIVATE_DEPENDENCIES) for inc in reach(src)):
            reaching.add(str(src.relative_to(ROOT)))
listed = {line.strip() for line in (ROOT / "cmake/internal-headers.txt").read_text().splitlines()
          if line.strip() and not line.startswith("#")}
for h in sorted(reaching - listed):
    violations.append(f"{h} reaches a private dependency: list it in cmake/internal-headers.txt")
for h in sorted(listed - reaching):
    violations.append(f"cmake/internal-headers.txt lists {h}, which is "
                      f"{'installable' if (ROOT / h).is_file() else 'not a file'}: remove it")

for v in violations:
    print(v)
checked = sum(len(sources(f)) for f in ("util", "geometry", "raster", "cli", "python"))
print(f"check_includes: {checked} files, {len(violations)} violations")
sys.exit(1 if violations else 0)
