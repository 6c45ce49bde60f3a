#pragma once
// What `umbra --version` prints: umbra's version, then one line per library
// it was built with, and the version it runs with where that can differ.
#include <string>

namespace umbra::cli {

/// "umbra 0.1.0\n" then "CGAL 5.5.1\n", "GMP 6.2.1\n" (or "GMP 6.2.1, built
/// with 6.2.0\n" when the loaded library differs from the headers), ...:
/// CGAL, GMP, MPFR, OpenMesh, nlohmann_json, OpenImageIO, Embree, oneTBB,
/// CLI11, fmt. No trailing newline (CLI11 adds one).
std::string version_text(const std::string& umbra_version);

}  // namespace umbra::cli
