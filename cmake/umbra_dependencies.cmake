# Every dependency comes from a Debian package (scripts/install-deps.sh).
find_package(CGAL REQUIRED)
find_package(OpenMesh CONFIG REQUIRED)  # CONFIG: CGAL ships a FindOpenMesh that fails here
find_package(OpenImageIO REQUIRED)
find_package(OpenEXR CONFIG REQUIRED)  # OpenEXR::OpenEXR and ::OpenEXRCore, PRIVATE to umbra_raster: raster/exr_encode.cpp
find_package(PNG REQUIRED)  # PNG::PNG, PRIVATE to umbra_raster: raster/png_encode.cpp
find_package(glm REQUIRED)
find_package(nlohmann_json REQUIRED)
find_package(simdjson REQUIRED)  # scene JSON (geometry/io/json_document.h)
find_package(CLI11 REQUIRED)
find_package(fmt REQUIRED)
find_package(TinyGLTF REQUIRED)  # TinyGLTF::TinyGLTF (README.Debian's plain name is wrong)
find_package(PROJ CONFIG REQUIRED)  # PROJ::proj, PRIVATE to umbra_geometry: geometry/export/geodetic_frame.cpp
find_package(Threads REQUIRED)
find_package(embree 3 REQUIRED)  # target `embree` (no namespace); Method::ray only, PRIVATE to umbra_raster
if(UMBRA_BUILD_TESTS)
  find_package(GTest REQUIRED)
  find_package(assimp REQUIRED)  # tests only: an independent reader of exported glTF volumes
endif()
if(UMBRA_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()

# Debian 12's OpenImageIO config lists /usr/include/opencv4 among its include
# directories although umbra's headers never need OpenCV; without
# libopencv-dev installed, CMake refuses the target. Drop the missing paths.
get_target_property(_oiio_includes OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
set(_oiio_existing)
foreach(_dir IN LISTS _oiio_includes)
  if(EXISTS "${_dir}")
    list(APPEND _oiio_existing "${_dir}")
  endif()
endforeach()
set_target_properties(OpenImageIO::OpenImageIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_oiio_existing}")
find_package(TBB REQUIRED)
# The `umbra` executable's allocator (cli/heap.cpp): mimalloc, its heap in
# transparent huge pages. Not under sanitizers, which replace malloc.
if(NOT UMBRA_SANITIZE AND NOT UMBRA_FUZZ)
  find_package(mimalloc 2 CONFIG REQUIRED)
endif()
