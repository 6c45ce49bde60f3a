# Included by tests/CMakeLists.txt: the command-line conventions of issue 24
# (docs/cli.md), run as a user would through umbra_cli_test.

# Parse errors name what is wrong and point to the verb's --help: an unknown
# option is reported before CLI11's checks of required options and verbs.
umbra_cli_test(no_verb_names_the_commands EXIT 2
  STDERR "^umbra: a command is required; commands: render, validate, volume, footprint, sunlight, merge, batch, fuzz \\(see 'umbra --help'\\)\n$")
umbra_cli_test(unknown_top_option ARGS --bogus EXIT 2
  STDERR "^umbra: unknown option '--bogus' \\(see 'umbra --help'\\)\n$")
umbra_cli_test(render_unknown_option ARGS render --bogus EXIT 2
  STDERR "^umbra: unknown option '--bogus' \\(see 'umbra render --help'\\)\n$")
umbra_cli_test(render_unknown_option_after_missing_scene ARGS render missing.json --bogus EXIT 2
  STDERR "^umbra: unknown option '--bogus' \\(see 'umbra render --help'\\)\n$")
umbra_cli_test(validate_unknown_short_option ARGS validate scene.json -x SETUP scene.json EXIT 2
  STDERR "^umbra: unknown option '-x' \\(see 'umbra validate --help'\\)\n$"
  ABSENT scene.mismatches.png)
umbra_cli_test(volume_missing_scene_points_to_volume_help ARGS volume EXIT 2
  STDERR "^umbra: SCENE is required \\(see 'umbra volume --help'\\)\n$")
umbra_cli_test(merge_error_points_to_merge_help ARGS merge EXIT 2
  STDERR "^umbra: [^\n]* \\(see 'umbra merge --help'\\)\n$")
umbra_cli_test(fuzz_unknown_option ARGS fuzz check --bogus EXIT 2
  STDERR "^umbra: unknown option '--bogus' \\(see 'umbra fuzz check --help'\\)\n$")
umbra_cli_test(fuzz_unknown_command ARGS fuzz nope EXIT 2
  STDERR "^umbra: unknown command 'nope'; commands: check, export, real, merge \\(see 'umbra fuzz --help'\\)\n$")

# --help shows defaults, also those of options that stay unset unless given
# (their defaults come from raster::ShadowMapOptions and RayOptions).
umbra_cli_test(render_help_shows_defaults ARGS render --help EXIT 0
  STDOUT "--method METHOD:[^\n]*=volume\n.*--map-resolution N:[^\n]*=2048\n.*--map-bias B:[^\n]*=4 .*--map-slope-bias S:[^\n]*=1\\.5\n.*--map-lookup KIND:[^\n]*=nearest\n.*--map-pcf K:[^\n]*=1 .*--ray-epsilon E:[^\n]*=1e-05\n.*--threads N:[^\n]*=0 .*--spp N:[^\n]*=1 ")
umbra_cli_test(validate_help_shows_defaults ARGS validate --help EXIT 0
  STDOUT "--samples N:[^\n]*=all .*--seed S:[^\n]*=1 ")
umbra_cli_test(fuzz_check_help_shows_defaults ARGS fuzz check --help EXIT 0
  STDOUT "--count [^\n]*=50 .*--width [^\n]*=32\n")
# The shown defaults are not applied as values: a render without --map-*
# options is not refused as if they were given.
umbra_cli_test(render_defaults_are_not_given_options
  ARGS render ${PROJECT_SOURCE_DIR}/data/scenes/open.json -o out.png -q EXIT 0 EXIST out.png)

# validate --no-mask writes no mask and reports it as null; with
# --stats-json - the JSON is all of stdout and the text summary goes to
# stderr. The image is copied so that the default mask would land in the
# work directory.
set(_local_mesh ${PROJECT_SOURCE_DIR}/tests/data/scenes/local_mesh)
umbra_cli_test(validate_no_mask ARGS validate ${_local_mesh}/scene.json --image render.exr
  --samples 300 --no-mask --stats-json - COPY ${_local_mesh}/render.exr EXIT 0
  STDOUT "^{\n[^\n]*\n[^\n]*\n  \"mask\": null,\n.*\n}\n$"
  STDERR "^validated render\\.exr [^\n]*\n.*\nOK: 0 mismatches; no mask written \\(--no-mask\\)\n$"
  ABSENT render.mismatches.png)
umbra_cli_test(validate_stats_json_stdout_moves_summary_to_stderr ARGS validate
  ${_local_mesh}/scene.json --image render.exr --samples 300 --mask m.png --stats-json -
  COPY ${_local_mesh}/render.exr EXIT 0
  STDOUT "^{\n[^\n]*\n[^\n]*\n  \"mask\": \"m\\.png\",\n.*\"seconds\": {.*\n}\n$"
  STDERR "^validated render\\.exr [^\n]*\n.*\nOK: 0 mismatches; mask written to m\\.png\n$"
  EXIST m.png)
umbra_cli_test(validate_summary_on_stdout_by_default ARGS validate
  ${_local_mesh}/scene.json --image render.exr --samples 300 COPY ${_local_mesh}/render.exr EXIT 0
  STDOUT "^validated render\\.exr [^\n]*\n.*\nOK: 0 mismatches; mask written to render\\.mismatches\\.png\n$"
  EXIST render.mismatches.png)
umbra_cli_test(validate_no_mask_excludes_mask ARGS validate ${_local_mesh}/scene.json
  --image ${_local_mesh}/render.exr --no-mask --mask m.png EXIT 2
  STDERR "^umbra: --mask excludes --no-mask \\(see 'umbra validate --help'\\)\n$" ABSENT m.png)
# Outputs in a directory that is not writable: refused before the work.
foreach(case
    "validate_mask;validate|${_local_mesh}/scene.json|--image|${_local_mesh}/render.exr|--mask|@DIR@/m.png"
    "validate_stats_json;validate|${_local_mesh}/scene.json|--image|${_local_mesh}/render.exr|--no-mask|--stats-json|@DIR@/s.json"
    "render_output;render|${PROJECT_SOURCE_DIR}/data/scenes/open.json|-o|@DIR@/out.png"
    "volume_output;volume|${PROJECT_SOURCE_DIR}/data/scenes/open.json|-o|@DIR@/out.ply")
  list(GET case 0 name)
  list(GET case 1 args)
  string(REPLACE "|" ";" args "${args}")
  add_test(NAME cli.${name}_in_unwritable_directory
    COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/cli/unwritable_directory.sh $<TARGET_FILE:umbra>
      ${CMAKE_CURRENT_BINARY_DIR}/cli/${name}_in_unwritable_directory ${args})
  set_tests_properties(cli.${name}_in_unwritable_directory PROPERTIES SKIP_RETURN_CODE 77)
endforeach()

# Volumes need no camera: a JSON or glTF scene without one exports; render
# and validate still refuse it with one line. A scene without a light is a
# warning, not an error, for every verb.
set(_no_camera ${PROJECT_SOURCE_DIR}/tests/data/scenes/no_camera)
umbra_cli_test(volume_json_without_camera ARGS volume ${_no_camera}/two_lights.json -o v.ply EXIT 0
  STDOUT "^wrote v\\.ply: [1-9][0-9]* faces [^\n]*light 0: [1-9][0-9]*, light 1: [1-9][0-9]*\\)" EXIST v.ply)
umbra_cli_test(volume_gltf_without_camera ARGS volume ${_no_camera}/two_lights.gltf -o v.obj EXIT 0
  STDOUT "^wrote v\\.obj \\+ v\\.obj\\.json \\+ v\\.mtl: [1-9][0-9]* faces" EXIST v.obj v.obj.json v.mtl)
umbra_cli_test(render_json_without_camera ARGS render ${_no_camera}/two_lights.json -o r.png EXIT 2
  STDERR "^umbra: [^\n]*two_lights\\.json: camera: missing required field 'camera'\n$" ABSENT r.png)
umbra_cli_test(render_gltf_without_camera ARGS render ${_no_camera}/two_lights.gltf -o r.png EXIT 2
  STDERR "^umbra: [^\n]*two_lights\\.gltf: cameras: no node of the scene instances a perspective camera[^\n]*\n$"
  ABSENT r.png)
umbra_cli_test(validate_without_camera ARGS validate ${_no_camera}/two_lights.json --image render.exr
  --no-mask COPY ${_local_mesh}/render.exr EXIT 2
  STDERR "^umbra: [^\n]*two_lights\\.json: camera: missing required field 'camera'\n$")
foreach(verb_out render:r.png volume:r.ply)
  string(REPLACE ":" ";" verb_out "${verb_out}")
  list(GET verb_out 0 verb)
  list(GET verb_out 1 out)
  umbra_cli_test(${verb}_warns_without_lights ARGS ${verb} ${_no_camera}/no_lights.json -o ${out} EXIT 0
    STDOUT "^wrote r\\." STDERR "^umbra: warning: [^\n]*no_lights\\.json: the scene has no lights; only ambient light, no shadow anywhere\n$"
    EXIST ${out})
endforeach()

# --exposure EV: within +-64 stops, finite; refused otherwise before any work.
foreach(ev 65 -64.5 nan inf x)
  string(MAKE_C_IDENTIFIER "${ev}" id)
  umbra_cli_test(render_exposure_${id} ARGS render scene.json --exposure ${ev} SETUP scene.json
    EXIT 2 STDERR "^umbra: --exposure: '${ev}' is not a finite number of stops from -64 to 64 \\(see 'umbra render --help'\\)\n$"
    ABSENT scene.png)
endforeach()
umbra_cli_test(render_exposure_minus_14 ARGS render ${PROJECT_SOURCE_DIR}/data/scenes/open.json
  --exposure -14 -o out.exr EXIT 0 STDOUT "^wrote out\\.exr " EXIST out.exr)

# -v/--verbose: a line per light and the times per phase on stderr, stdout
# unchanged; -q and -v exclude each other on every verb that has both.
umbra_cli_test(render_verbose ARGS render ${PROJECT_SOURCE_DIR}/data/scenes/two_lights.json
  -o out.png -v EXIT 0 STDOUT "^wrote out\\.png \\([^\n]*\n$"
  STDERR "light 0: point at \\(3, 6, 3\\), light_end 12\nlight 1: directional toward \\(1, -2, -0\\.5\\)\ncounts: 76800 pixels, [^\n]*\nseconds: load [0-9.]+, volumes [^\n]*total [0-9.]+\n$"
  EXIST out.png)
umbra_cli_test(volume_verbose ARGS volume ${PROJECT_SOURCE_DIR}/data/scenes/two_lights.json
  -o out.ply --verbose EXIT 0
  STDERR "^light 0: point at [^\n]*: [0-9]+ faces \\(type 1: [^\n]*\nlight 1: directional [^\n]*\nseconds: load [^\n]*\n$"
  EXIST out.ply)
umbra_cli_test(validate_verbose ARGS validate ${_local_mesh}/scene.json --image render.exr
  --samples 100 --no-mask -v COPY ${_local_mesh}/render.exr EXIT 0
  STDERR "^seconds: load [0-9.]+, read [0-9.]+, validate [0-9.]+, write [0-9.]+\n$")
umbra_cli_test(footprint_verbose ARGS footprint
  ${PROJECT_SOURCE_DIR}/data/scenes/two_lights.json --ignore-light-end -o out.ply -v EXIT 0
  STDOUT "^wrote out\\.ply: [0-9]+ regions [^\n]*\n$"
  STDERR "^light 0: point at \\(3, 6, 3\\), light_end 12 \\(ignored\\): [0-9]+ regions on [0-9]+ receiver polygons, shadowed [0-9.e+-]+ of [0-9.e+-]+\nlight 1: directional toward \\(1, -2, -0\\.5\\): [0-9]+ regions on [0-9]+ receiver polygons, shadowed [^\n]*\nseconds: load [0-9.]+, volumes [0-9.]+, partition [0-9.]+, write [0-9.]+, total [0-9.]+\n$"
  EXIST out.ply)
foreach(verb render volume validate footprint)
  set(_image "")
  if(verb STREQUAL "validate")
    set(_image --image r.exr)
  endif()
  umbra_cli_test(${verb}_quiet_excludes_verbose ARGS ${verb} scene.json ${_image} -q -v
    SETUP scene.json r.exr
    EXIT 2 STDERR "^umbra: --(quiet excludes --verbose|verbose excludes --quiet) \\(see 'umbra ${verb} --help'\\)\n$")
endforeach()

# Bash completion against the real executable (cli/umbra-completion.bash).
add_test(NAME cli.bash_completion
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/completion_test.sh
    ${CMAKE_BINARY_DIR}/share/bash-completion/completions/umbra $<TARGET_FILE:umbra>
    ${CMAKE_CURRENT_BINARY_DIR}/cli/completion)
# The man pages help2man wrote at build time: one per verb, titled and named
# for it, with the verb's options.
if(UMBRA_HELP2MAN)
  add_test(NAME cli.man_pages
    COMMAND sh -c "set -e; d=${CMAKE_BINARY_DIR}/man
      grep -q '^\\.TH UMBRA ' $d/umbra.1
      grep -q '^\\.TH UMBRA-RENDER ' $d/umbra-render.1
      grep -q '^umbra-render \\\\- Render a scene with its shadows' $d/umbra-render.1
      grep -q 'map\\\\-resolution' $d/umbra-render.1
      grep -q 'stats\\\\-json' $d/umbra-validate.1
      grep -q '^umbra-fuzz \\\\- degenerate scenes' $d/umbra-fuzz.1
      grep -q 'umbra-batch(1)' $d/umbra-merge.1
      test $(ls $d/*.1 | wc -l) -eq 9")
endif()

# The installed C++ package: staged, moved, consumed by CMake and pkg-config
# (tests/consumer, docs/api.md). Not in sanitizer builds, which install
# nothing.
if(UMBRA_INSTALLABLE)
  add_test(NAME package.installed
    COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${CMAKE_BINARY_DIR} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
      -DWORK=${CMAKE_CURRENT_BINARY_DIR}/package -DSCENE=${PROJECT_SOURCE_DIR}/data/scenes/default.json
      -DUMBRA=$<TARGET_FILE:umbra> -DCXX=${CMAKE_CXX_COMPILER}
      -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/installed_package.cmake)
endif()
