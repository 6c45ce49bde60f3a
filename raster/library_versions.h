#pragma once
// The versions of the libraries umbra::raster is built with and runs with
// (`umbra --version`). OpenImageIO is queried behind the image I/O file,
// OpenEXR behind its writer and Embree behind raster/methods/, as everything
// else that includes them.
#include <umbra/geometry/library_versions.h>

namespace umbra::raster {

/// OpenImageIO (raster/image_io.cpp).
geometry::LibraryVersion openimageio_version();

/// OpenEXR, which writes umbra's .exr files (raster/exr_encode.cpp).
geometry::LibraryVersion openexr_version();

/// Embree (raster/methods/embree_scene.cpp).
geometry::LibraryVersion embree_version();

}  // namespace umbra::raster
