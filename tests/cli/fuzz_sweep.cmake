# Runs one of umbra's fuzzing sweeps as a CI slice and judges the tool:
#   cmake -DUMBRA=<exe> -DARGS=<a|b|c> -DSUMMARY_REGEX=<re>
#         [-DJSON_MIN=<key=n|key=n>] -P fuzz_sweep.cmake
# Passes when the sweep ran to its end with exit 0 (every scene passed),
# its summary on stdout matches SUMMARY_REGEX, and, with JSON_MIN (the sweep
# ran with --json), every named count of the JSON summary is at least n.
# Exit 1 (scenes failed: each is printed with its recipe), 2 or 3 (bad
# usage, internal error outside a scene) fails.
cmake_minimum_required(VERSION 3.25)

foreach(var UMBRA ARGS SUMMARY_REGEX)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "fuzz_sweep.cmake: ${var} is not set")
  endif()
endforeach()
string(REPLACE "|" ";" args "${ARGS}")

execute_process(COMMAND "${UMBRA}" ${args}
  RESULT_VARIABLE exit_code OUTPUT_VARIABLE out ERROR_VARIABLE err)

set(failures "")
if(NOT exit_code MATCHES "^[01]$")
  string(APPEND failures "exit code ${exit_code}: the sweep did not run to its end\n")
elseif(NOT exit_code STREQUAL "0")
  string(APPEND failures "exit code ${exit_code}: scenes failed\n")
endif()
if(NOT out MATCHES "${SUMMARY_REGEX}")
  string(APPEND failures "stdout does not match '${SUMMARY_REGEX}'\n")
endif()
string(REPLACE "|" ";" minimums "${JSON_MIN}")
foreach(pair IN LISTS minimums)
  string(REPLACE "=" ";" kv "${pair}")
  list(GET kv 0 key)
  list(GET kv 1 least)
  string(JSON value ERROR_VARIABLE json_error GET "${out}" "${key}")
  if(json_error)
    string(APPEND failures "no '${key}' in the JSON summary: ${json_error}\n")
  elseif(value LESS least)
    string(APPEND failures "${key} = ${value}, expected at least ${least}\n")
  endif()
endforeach()

if(failures)
  message(FATAL_ERROR "umbra ${args}\n--- stdout:\n${out}\n--- stderr:\n${err}\n--- failures:\n${failures}")
endif()
# What it found, for `ctest -V -L sweep`: the failing scenes and their recipes.
string(REGEX MATCHALL "FAIL [^\n]*" found "${out}\n${err}")
list(LENGTH found n)
message(STATUS "umbra ${args}: exit ${exit_code}, ${n} failing scenes reported")
foreach(line IN LISTS found)
  message(STATUS "${line}")
endforeach()
