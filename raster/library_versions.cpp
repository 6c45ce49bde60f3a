#include <raster/library_versions.h>

namespace umbra::raster {

std::vector<geometry::LibraryVersion> raster_library_versions() {
  return {openimageio_version(), embree_version()};
}

}  // namespace umbra::raster
