# Renders a scene with umbra and validates the EXR against the exact oracle:
#   cmake -DUMBRA=<exe> -DSCENE=<json> -DWORK_DIR=<dir> -DMETHOD=<volume|exact>
#         [-DMIN_BOUNDARY=<n>] [-DRANGE_ONLY=ON] -P render_validate.cmake
# Fails unless both commands exit 0, every pixel was checked, every light was
# compared on some pixels, no light has a mismatch, the mask PNG exists, and
# at least MIN_BOUNDARY samples (all lights together) were boundary samples.
# RANGE_ONLY (a float method, map or ray, whose shadow edges may alias):
# validate may exit 1 with mismatches, but no light may have a sample whose
# range (in or out) differs from the oracle's (wrong_range 0).
cmake_minimum_required(VERSION 3.25)

foreach(var UMBRA SCENE WORK_DIR METHOD)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "render_validate.cmake: ${var} is not set")
  endif()
endforeach()
if(NOT DEFINED MIN_BOUNDARY)
  set(MIN_BOUNDARY 0)
endif()
set(ok_exits 0)
if(RANGE_ONLY)
  set(ok_exits 0 1)
endif()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(exr "${WORK_DIR}/render.exr")
set(mask "${WORK_DIR}/mask.png")

execute_process(COMMAND "${UMBRA}" render "${SCENE}" -o "${exr}" --method "${METHOD}" -q
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT EXISTS "${exr}")
  message(FATAL_ERROR "render exited ${code}\n${out}\n${err}")
endif()

set(stats "${WORK_DIR}/validate.json")
execute_process(COMMAND "${UMBRA}" validate "${SCENE}" --image "${exr}" --mask "${mask}" --json
  --stats-json "${stats}"
  RESULT_VARIABLE code OUTPUT_VARIABLE report ERROR_VARIABLE err)
if(NOT code IN_LIST ok_exits)
  message(FATAL_ERROR "validate exited ${code}\n${report}\n${err}")
endif()
if(NOT EXISTS "${mask}")
  message(FATAL_ERROR "validate wrote no mask at ${mask}")
endif()

# --stats-json holds the same report plus the time of every phase.
file(READ "${stats}" stats_text)
string(JSON stats_mismatches GET "${stats_text}" total_mismatches)
string(JSON seconds_validate GET "${stats_text}" seconds validate)
string(JSON total GET "${report}" total_mismatches)
if(NOT stats_mismatches EQUAL total OR seconds_validate LESS 0)
  message(FATAL_ERROR "--stats-json disagrees with --json:\n${stats_text}")
endif()
string(JSON width GET "${report}" width)
string(JSON height GET "${report}" height)
string(JSON checked GET "${report}" pixels_checked)
math(EXPR expected "${width} * ${height}")
if(NOT checked EQUAL expected)
  message(FATAL_ERROR "checked ${checked} pixels of ${expected}\n${report}")
endif()
if(NOT total EQUAL 0 AND NOT RANGE_ONLY)
  message(FATAL_ERROR "${total} mismatches\n${report}")
endif()

string(JSON lights LENGTH "${report}" lights)
math(EXPR last "${lights} - 1")
set(boundary 0)
foreach(i RANGE ${last})
  string(JSON compared GET "${report}" lights ${i} compared)
  string(JSON b GET "${report}" lights ${i} boundary)
  # An area light's report has no range (its answer is a fraction).
  string(JSON wrong_range ERROR_VARIABLE no_range GET "${report}" lights ${i} wrong_range)
  if(no_range)
    set(wrong_range 0)
  endif()
  if(compared EQUAL 0)
    message(FATAL_ERROR "light ${i} was compared on no pixel\n${report}")
  endif()
  if(NOT wrong_range EQUAL 0)
    message(FATAL_ERROR "light ${i}: ${wrong_range} samples with the wrong range\n${report}")
  endif()
  math(EXPR boundary "${boundary} + ${b}")
endforeach()
if(boundary LESS MIN_BOUNDARY)
  message(FATAL_ERROR "${boundary} boundary samples, expected at least ${MIN_BOUNDARY}\n${report}")
endif()
message(STATUS "${SCENE} (${METHOD}): ${checked} pixels, ${boundary} boundary, ${total} mismatches")
