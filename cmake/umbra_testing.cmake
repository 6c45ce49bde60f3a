# CTest labels (CONTRIBUTING.md): every test is `fast` or `slow`; tests
# that run an umbra program (CMake-script tests, replays, smoke runs) are
# also `cli`; those that feed umbra hostile input (fuzz replays, fuzz.check,
# the CLI's refusals) are also `edge`, the sanitizer slice CI runs.
# `ctest -L fast` is the inner loop (under a minute here);
# `slow` holds the sweeps, the chart smoke run, the 1,024-lamp city, the
# determinism runs and the area-light scenes (their exact visible fractions
# take seconds a frame; the gtests prove the same code under sanitizers).
set(UMBRA_NOT_CLI_TESTS_REGEX "^layout\\.")
set(UMBRA_SLOW_TESTS_REGEX
  "^(fuzz\\.real\\.|fuzz\\.check\\.placements|bench\\.chart_smoke|bench\\.city_|determinism\\.|regression\\.|validate\\..*\\.exact$|validate\\.soft|tiles\\.soft|sun\\.year)")

# Labels every test that add_test made in the calling directory.
function(umbra_label_directory_tests)
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach(t IN LISTS tests)
    if(t MATCHES "${UMBRA_SLOW_TESTS_REGEX}")
      set_property(TEST ${t} APPEND PROPERTY LABELS slow)
    else()
      set_property(TEST ${t} APPEND PROPERTY LABELS fast)
    endif()
    if(NOT t MATCHES "${UMBRA_NOT_CLI_TESTS_REGEX}")
      set_property(TEST ${t} APPEND PROPERTY LABELS cli)
    endif()
  endforeach()
endfunction()

# A GoogleTest executable: its test cases discovered and labelled `fast`,
# except those matching the gtest filter SLOW (e.g. "RealModels.*"), which
# are `slow`; LABELS adds labels to all.
function(umbra_discover_gtests target)
  cmake_parse_arguments(G "" "SLOW" "LABELS" ${ARGN})
  if(G_SLOW)
    gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 TEST_FILTER "-${G_SLOW}"
      PROPERTIES LABELS "fast;${G_LABELS}")
    gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 TEST_FILTER "${G_SLOW}"
      PROPERTIES LABELS "slow;${G_LABELS}")
  else()
    gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 PROPERTIES LABELS "fast;${G_LABELS}")
  endif()
endfunction()
