# The installed package (docs/api.md): include/umbra/<folder>/ headers,
# shared libraries umbra::util, umbra::geometry and umbra::raster, the image
# module, umbraConfig.cmake and umbra.pc; and the programs, man pages and
# completion. The shared libraries are linked from the static libraries'
# own objects (position-independent; nothing is compiled twice), so their
# private dependencies (CGAL, OpenMesh, Embree, ...) stay inside them: a
# consumer finds only what the headers expose, TBB.
include(CMakePackageConfigHelpers)

set(UMBRA_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/umbra)

# STATIC's objects as the shared library umbra::EXPORT_NAME, linked as STATIC
# is: its public libraries public, the rest private, umbra's own mapped to
# their shared twins.
function(umbra_shared_library static export_name)
  set(shared ${static}_shared)
  add_library(${shared} SHARED $<TARGET_OBJECTS:${static}>)
  get_target_property(all ${static} LINK_LIBRARIES)
  get_target_property(interface ${static} INTERFACE_LINK_LIBRARIES)
  set(public)
  set(private)
  foreach(lib IN LISTS all)
    set(mapped ${lib})
    if(lib MATCHES "^umbra::(util|geometry|raster)$")
      set(mapped umbra_${CMAKE_MATCH_1}_shared)
    endif()
    if(lib IN_LIST interface)
      list(APPEND public ${mapped})
    else()
      list(APPEND private ${mapped})
    endif()
  endforeach()
  target_link_libraries(${shared} PUBLIC ${public} PRIVATE ${private})
  umbra_library_interface(${shared})
  target_compile_features(${shared} INTERFACE cxx_std_20)
  # Only umbra's symbols are exported (cmake/umbra.map); every reference
  # resolved at link time, none left to the consumer.
  target_link_options(${shared} PRIVATE
    -Wl,--version-script=${PROJECT_SOURCE_DIR}/cmake/umbra.map -Wl,--no-undefined)
  set_target_properties(${shared} PROPERTIES
    OUTPUT_NAME ${static} EXPORT_NAME ${export_name}
    LINK_DEPENDS ${PROJECT_SOURCE_DIR}/cmake/umbra.map
    # Each finds its siblings wherever the installed tree is moved.
    INSTALL_RPATH "$ORIGIN"
    VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
endfunction()

umbra_shared_library(umbra_util util)
umbra_shared_library(umbra_geometry geometry)
umbra_shared_library(umbra_raster raster)

install(TARGETS umbra_util_shared umbra_geometry_shared umbra_raster_shared EXPORT umbraTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
# Found by the loader beside libumbra_raster.so, in its umbra/ folder
# (raster/image_codec_loader.cpp), wherever the tree is moved.
install(TARGETS umbra_image_codec LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/umbra)
install(EXPORT umbraTargets NAMESPACE umbra:: DESTINATION ${UMBRA_CMAKE_DIR})

# Every header but those that reach a private dependency.
file(STRINGS ${PROJECT_SOURCE_DIR}/cmake/internal-headers.txt internal_headers REGEX "^[a-z]")
foreach(folder IN ITEMS util geometry raster)
  file(GLOB_RECURSE headers RELATIVE ${PROJECT_SOURCE_DIR} CONFIGURE_DEPENDS
    ${PROJECT_SOURCE_DIR}/${folder}/*.h)
  foreach(header IN LISTS headers)
    if(NOT header IN_LIST internal_headers)
      get_filename_component(dir ${header} DIRECTORY)
      install(FILES ${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/umbra/${dir})
    endif()
  endforeach()
endforeach()

configure_package_config_file(cmake/umbraConfig.cmake.in
  ${PROJECT_BINARY_DIR}/umbraConfig.cmake INSTALL_DESTINATION ${UMBRA_CMAKE_DIR})
# 0.x: a minor release may change the API (SameMinorVersion), as the
# libraries' SOVERSION says.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/umbraConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/umbraConfig.cmake ${PROJECT_BINARY_DIR}/umbraConfigVersion.cmake
  DESTINATION ${UMBRA_CMAKE_DIR})

# pkg-config: the prefix relative to the .pc file, so the tree can move.
file(RELATIVE_PATH UMBRA_PC_PREFIX ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" UMBRA_PC_PREFIX "${UMBRA_PC_PREFIX}")
configure_file(cmake/umbra.pc.in ${PROJECT_BINARY_DIR}/umbra.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/umbra.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# The programs: `umbra fuzz` runs umbra-fuzz from beside umbra; both find
# the image module in ../<libdir>/umbra.
install(TARGETS umbra umbra_fuzz_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET umbra_man_pages)
  install(DIRECTORY ${PROJECT_BINARY_DIR}/man/ DESTINATION ${CMAKE_INSTALL_MANDIR}/man1
    FILES_MATCHING PATTERN "*.1")
endif()
install(FILES ${PROJECT_BINARY_DIR}/share/bash-completion/completions/umbra
  DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
