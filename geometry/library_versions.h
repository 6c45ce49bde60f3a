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

/// "major.minor.patch".
std::string dotted_version(int major, int minor, int patch);

/// A version packed in decimal digits as major·10000 + minor·100 + patch,
/// as fmt's FMT_VERSION and OpenImageIO's numbers are (20407: "2.4.7").
std::string decimal_packed_version(int packed);

}  // namespace umbra::geometry
