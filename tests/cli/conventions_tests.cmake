# Included by tests/CMakeLists.txt: the command-line conventions of issue 24
# (docs/cli.md), run as a user would through umbra_cli_test.

# Parse errors name what is wrong and point to the verb's --help: an unknown
# option is reported before CLI11's checks of required options and verbs.
umbra_cli_test(no_verb_names_the_commands EXIT 2
  STDERR "^umbra: a command is required; commands: render, validate, volume, merge, fuzz \\(see 'umbra --help'\\)\n$")
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
  STDERR "^umbra: unknown command 'nope'; commands: check, export, real \\(see 'umbra fuzz --help'\\)\n$")

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
