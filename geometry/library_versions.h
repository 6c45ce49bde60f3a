#pragma once
// The versions of the libraries umbra::geometry is built with and runs with
// (`umbra --version`). CGAL, GMP and MPFR are queried here, so that nothing
// outside geometry/ includes them; raster/library_versions.h adds its own.
#include <string>
#include <vector>

namespace umbra::geometry {

struct LibraryVersion {
  std::string name;   ///< "CGAL", "GMP", ...
  std::string built;  ///< from the headers umbra was compiled against
  std::string runs;   ///< from the shared library loaded now; empty: header-only or not queryable
};

/// CGAL, GMP, MPFR, OpenMesh and nlohmann_json, in that order.
std::vector<LibraryVersion> geometry_library_versions();

}  // namespace umbra::geometry
