#include <CLI/CLI.hpp>
#include <cli/version_text.h>
#include <umbra/geometry/library_versions.h>
#include <umbra/raster/library_versions.h>

#include <fmt/format.h>
#include <oneapi/tbb/version.h>

#include <vector>

namespace umbra::cli {

std::string version_text(const std::string& umbra_version) {
  std::vector<geometry::LibraryVersion> libraries = geometry::geometry_library_versions();
  libraries.push_back(raster::openimageio_version());
  libraries.push_back(raster::openexr_version());
  libraries.push_back(raster::embree_version());
  libraries.push_back({"oneTBB", TBB_VERSION_STRING, TBB_runtime_version()});
  libraries.push_back({"CLI11", CLI11_VERSION, ""});  // header-only
  libraries.push_back({"fmt", geometry::decimal_packed_version(FMT_VERSION), ""});
  std::string text = "umbra " + umbra_version;
  for (const geometry::LibraryVersion& v : libraries) {
    // The version running, and the headers' when they differ.
    if (v.runs.empty() || v.runs == v.built)
      text += fmt::format("\n{} {}", v.name, v.built);
    else
      text += fmt::format("\n{} {}, built with {}", v.name, v.runs, v.built);
  }
  return text;
}

}  // namespace umbra::cli
