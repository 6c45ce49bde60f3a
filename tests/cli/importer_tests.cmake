# Included by tests/CMakeLists.txt: exported volumes and footprints read by
# independent importers (issue 24, docs/volume-export.md "Importers"), and
# the volume export's --ply-format option. The assimp checks are GoogleTests
# (tests/geometry/export/volume_importers_test.cpp, gltf_writer_test.cpp).
set(_scenes ${PROJECT_SOURCE_DIR}/data/scenes)

umbra_cli_test(volume_ply_ascii ARGS volume ${_scenes}/default.json -o vol.ply --ply-format ASCII
  EXIT 0 STDOUT "^wrote vol\\.ply: " EXIST vol.ply ABSENT vol.ply.json)
umbra_cli_test(volume_ply_format_needs_a_ply ARGS volume scene.json -o vol.obj --ply-format ascii
  SETUP scene.json EXIT 2 STDERR "^umbra: --ply-format: applies to a \\.ply output only\n$"
  ABSENT vol.obj vol.obj.json vol.mtl)
umbra_cli_test(volume_ply_format_unknown ARGS volume scene.json -o vol.ply --ply-format text
  SETUP scene.json EXIT 2 STDERR "^umbra: --ply-format: [^\n]*text[^\n]*\n$" ABSENT vol.ply)
umbra_cli_test(volume_obj_name_with_whitespace ARGS volume scene.json -o "my vol.obj"
  SETUP scene.json EXIT 2
  STDERR "^umbra: my vol\\.obj: an \\.obj volume name cannot hold whitespace: its mtllib line names the \\.mtl sidecar\n$"
  ABSENT "my vol.obj" "my vol.obj.json" "my vol.mtl")
umbra_cli_test(volume_mtl_names_the_stats ARGS volume scene.json -o v.obj --stats-json v.mtl
  SETUP scene.json EXIT 2 STDERR "^umbra: v\\.mtl: --stats-json names the materials of -o"
  ABSENT v.obj v.obj.json)

# meshio (Debian's python3-meshio, hence /usr/bin/python3) reads the ASCII
# PLY and the OBJ of two scenes (the glTF one has triangles and quads); counts
# from the binary PLY's own faces.
foreach(scene two_lights.json gltf/two_lights.glb)
  string(REGEX REPLACE "[/.]" "_" _name "${scene}")
  add_test(NAME cli.volume_meshio_${_name}
    COMMAND sh -c "mkdir -p \"$3\" && \"$1\" volume \"$2\" -q -o \"$3/v.ply\" && \"$1\" volume \"$2\" -q -o \"$3/a.ply\" --ply-format ascii && \"$1\" volume \"$2\" -q -o \"$3/v.obj\" && /usr/bin/python3 \"$4\" \"$3/v.ply\" \"$3/a.ply\" \"$3/v.obj\""
      sh $<TARGET_FILE:umbra> ${_scenes}/${scene}
      ${CMAKE_CURRENT_BINARY_DIR}/cli/volume_meshio_${_name}
      ${CMAKE_CURRENT_SOURCE_DIR}/cli/volume_meshio_check.py)
  set_tests_properties(cli.volume_meshio_${_name} PROPERTIES SKIP_RETURN_CODE 77)
endforeach()

# The Khronos glTF validator on volume and footprint .gltf/.glb: no errors.
add_test(NAME cli.gltf_validator
  COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/cli/gltf_validate.sh $<TARGET_FILE:umbra>
    ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/cli/gltf_validator)
set_tests_properties(cli.gltf_validator PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300)
