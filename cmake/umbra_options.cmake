# Flags every umbra target links through `umbra::options`.
add_library(umbra_options INTERFACE)
add_library(umbra::options ALIAS umbra_options)

target_compile_options(umbra_options INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
  # Exactness starts with reproducible doubles: never contract a*b+c into an
  # FMA (it changes the sign of naive determinants on degenerate input), and
  # never -ffast-math. CGAL's own target adds -frounding-math for its filters.
  -ffp-contract=off)
# The project's own folders (cli/, tests/, fuzz/, ...) are included from the
# root: `#include <tests/support/work_dir.h>`. The libraries' headers go by
# their installed names, `<umbra/geometry/scene.h>` (UMBRA_BUILD_INCLUDE_DIR below).
target_include_directories(umbra_options INTERFACE ${PROJECT_SOURCE_DIR})

# CI builds with warnings as errors (scripts/test.sh); a user's build of a
# newer compiler should not fail on a warning it adds.
option(UMBRA_WERROR "Treat compiler warnings as errors" OFF)
if(UMBRA_WERROR)
  target_compile_options(umbra_options INTERFACE -Werror)
endif()

if(UMBRA_SANITIZE)
  target_compile_options(umbra_options INTERFACE
    -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  target_link_options(umbra_options INTERFACE -fsanitize=address,undefined)
endif()

# libFuzzer builds (fuzz/, docs/fuzzing.md): clang only. Every target gets
# coverage instrumentation (fuzzer-no-link) and ASan+UBSan; the harness
# executables alone link libFuzzer's main (fuzz/CMakeLists.txt).
if(UMBRA_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "UMBRA_FUZZ=ON needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++-14")
  endif()
  target_compile_options(umbra_options INTERFACE
    -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g)
  target_link_options(umbra_options INTERFACE -fsanitize=address,undefined)
endif()

# The libraries' headers are included as <umbra/geometry/...>,
# <umbra/raster/...>, <umbra/util/...> in the tree as once installed, so a
# consumer's own <geometry/...> never collides with umbra's. In the build
# tree include/umbra/<folder> links to the source folder (the folders stay at
# the top level, DESIGN.md's layout); installed, the headers are copied there.
set(UMBRA_BUILD_INCLUDE_DIR ${PROJECT_BINARY_DIR}/include)
file(MAKE_DIRECTORY ${UMBRA_BUILD_INCLUDE_DIR}/umbra)
foreach(folder IN ITEMS util geometry raster)
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${folder} ${UMBRA_BUILD_INCLUDE_DIR}/umbra/${folder} SYMBOLIC)
endforeach()

# What a library's interface carries to whoever links it, built here or
# installed: its headers and the exactness flag (warnings stay ours).
function(umbra_library_interface target)
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${UMBRA_BUILD_INCLUDE_DIR}> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  # Exactness, not style: the inline float code in the headers (interval
  # bounds, error bounds proved for separate roundings) is proved for
  # uncontracted arithmetic, so a consumer compiles it that way too.
  target_compile_options(${target} PUBLIC -ffp-contract=off)
  # Private: a project that adds umbra with add_subdirectory gets neither
  # our warnings nor our source root on its include path. umbra's own
  # programs, tests and benchmarks link umbra::options themselves.
  target_link_libraries(${target} PRIVATE $<BUILD_INTERFACE:umbra::options>)
endfunction()
