# Flags every umbra target links through `umbra::options`.
add_library(umbra_options INTERFACE)
add_library(umbra::options ALIAS umbra_options)

target_compile_options(umbra_options INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
  # Exactness starts with reproducible doubles: never contract a*b+c into an
  # FMA (it changes the sign of naive determinants on degenerate input), and
  # never -ffast-math. CGAL's own target adds -frounding-math for its filters.
  -ffp-contract=off)
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
