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
