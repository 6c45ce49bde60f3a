#include <umbra/geometry/library_versions.h>

#include <CGAL/version.h>
#include <OpenMesh/Core/System/config.h>
#include <fmt/format.h>
#include <gmp.h>
#include <mpfr.h>
#include <nlohmann/json.hpp>

namespace umbra::geometry {

std::string dotted_version(int major, int minor, int patch) {
  return fmt::format("{}.{}.{}", major, minor, patch);
}

std::string decimal_packed_version(int packed) {
  return dotted_version(packed / 10000, packed / 100 % 100, packed % 100);
}

std::vector<LibraryVersion> geometry_library_versions() {
  return {
      {"CGAL", CGAL_VERSION_STR, ""},  // header-only
      {"GMP", dotted_version(__GNU_MP_VERSION, __GNU_MP_VERSION_MINOR, __GNU_MP_VERSION_PATCHLEVEL),
       gmp_version},
      {"MPFR", MPFR_VERSION_STRING, mpfr_get_version()},
      // OM_VERSION is 0xMMmmpp in hex digits (0x90000: 9.0.0).
      {"OpenMesh",
       dotted_version((OM_VERSION >> 16) & 0xff, (OM_VERSION >> 8) & 0xff, OM_VERSION & 0xff), ""},
      {"nlohmann_json",
       dotted_version(NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR,
                      NLOHMANN_JSON_VERSION_PATCH),
       ""},  // header-only
  };
}

}  // namespace umbra::geometry
