# Extracts CGAL's data/meshes (Debian's libcgal-demo) into DEST once, where
# scripts/cgal-meshes.sh --all puts them: the real-model sweep's CI slice
# walks them.
#   cmake -DTARBALL=<data.tar.gz> -DDEST=<dir> -P extract_cgal_meshes.cmake
cmake_minimum_required(VERSION 3.25)
if(EXISTS "${DEST}/.all-meshes")
  return()
endif()
if(NOT EXISTS "${TARBALL}")
  message(FATAL_ERROR "${TARBALL} is absent: install Debian's libcgal-demo (scripts/install-deps.sh)")
endif()
file(MAKE_DIRECTORY "${DEST}")
file(ARCHIVE_EXTRACT INPUT "${TARBALL}" DESTINATION "${DEST}" PATTERNS data/meshes)
file(TOUCH "${DEST}/.all-meshes")
