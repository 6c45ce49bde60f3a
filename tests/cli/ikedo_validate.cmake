# Ikedo's penumbra end to end: `umbra render --method map --map-variant
# ikedo` then `umbra validate`, on an area-light scene:
#   cmake -DUMBRA=<exe> -DSCENE=<json> -DWORK_DIR=<dir> -P ikedo_validate.cmake
# It is a comparator: validate must find V errors (exit 1), score every
# sample of the area light, and print the same numbers as text and JSON.
# His coefficient set d erodes the umbra (D falls to 1/100 far from an
# occluder), so its mean error must exceed set a's, which keeps D = 1 up
# to x = 1.
cmake_minimum_required(VERSION 3.25)

foreach(var UMBRA SCENE WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "ikedo_validate.cmake: ${var} is not set")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

foreach(set a d)
  set(exr "${WORK_DIR}/${set}.exr")
  execute_process(COMMAND "${UMBRA}" render "${SCENE}" -o "${exr}" --method map
    --map-variant ikedo --ikedo-coeffs ${set} --map-resolution 1024 -q
    RESULT_VARIABLE code ERROR_VARIABLE err)
  if(NOT code EQUAL 0 OR NOT EXISTS "${exr}")
    message(FATAL_ERROR "render --ikedo-coeffs ${set} exited ${code}\n${err}")
  endif()
  execute_process(COMMAND "${UMBRA}" validate "${SCENE}" --image "${exr}" --samples 5000
    RESULT_VARIABLE code OUTPUT_VARIABLE text ERROR_VARIABLE err)
  if(NOT code EQUAL 1)
    message(FATAL_ERROR "validate of set ${set} exited ${code} (expected 1: V errors)\n${text}${err}")
  endif()
  execute_process(COMMAND "${UMBRA}" validate "${SCENE}" --image "${exr}" --samples 5000 --json
    RESULT_VARIABLE code OUTPUT_VARIABLE report ERROR_VARIABLE err)
  string(JSON kind GET "${report}" lights 0 kind)
  string(JSON compared GET "${report}" lights 0 compared)
  string(JSON mismatches GET "${report}" lights 0 mismatches)
  string(JSON largest GET "${report}" lights 0 max_error)
  string(JSON mean_${set} GET "${report}" lights 0 mean_error)
  message(STATUS "set ${set}: ${compared} compared, ${mismatches} over 1e-6, largest ${largest}, "
    "mean ${mean_${set}}")
  if(NOT kind STREQUAL "area" OR compared LESS 3000 OR mismatches LESS 1)
    message(FATAL_ERROR "set ${set}: ${kind} light, ${compared} compared, ${mismatches} mismatches")
  endif()
  if(largest GREATER 1 OR NOT largest GREATER 0)
    message(FATAL_ERROR "set ${set}: largest error ${largest}")
  endif()
  # The text summary says the same.
  if(NOT text MATCHES "light 0 \\(area\\): ${compared} compared, [0-9]+ boundary, ${mismatches} mismatches")
    message(FATAL_ERROR "set ${set}: the text summary differs from the JSON\n${text}")
  endif()
endforeach()
if(NOT mean_d GREATER mean_a)
  message(FATAL_ERROR "set d's mean error ${mean_d} is not above set a's ${mean_a}")
endif()
