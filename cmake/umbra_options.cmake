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

if(UMBRA_SANITIZE)
  target_compile_options(umbra_options INTERFACE
    -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  target_link_options(umbra_options INTERFACE -fsanitize=address,undefined)
endif()
