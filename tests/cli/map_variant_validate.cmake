# The source papers' map variants end to end: `umbra render --method map
# --map-variant V` then `umbra validate`, on the L prism whose arm shadows
# its own foot (tests/data/scenes/map_variants/l_self_shadow.json):
#   cmake -DUMBRA=<exe> -DSCENE=<json> -DWORK_DIR=<dir> -P map_variant_validate.cmake
# Ikedo's ID per object must miss the foot's self-shadow (hundreds of
# false-lit samples the depth map gets right) and make no false-shadowed
# sample; an ID per polygon and Williams' post-process must score as the
# depth map does, within an edge's aliasing.
cmake_minimum_required(VERSION 3.25)

foreach(var UMBRA SCENE WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "map_variant_validate.cmake: ${var} is not set")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

foreach(variant depth id id-polygon post)
  set(exr "${WORK_DIR}/${variant}.exr")
  execute_process(COMMAND "${UMBRA}" render "${SCENE}" -o "${exr}" --method map
    --map-variant ${variant} -q RESULT_VARIABLE code ERROR_VARIABLE err)
  if(NOT code EQUAL 0 OR NOT EXISTS "${exr}")
    message(FATAL_ERROR "render --map-variant ${variant} exited ${code}\n${err}")
  endif()
  # Exit 0 (no mismatch) or 1 (mismatches found): both are scores.
  execute_process(COMMAND "${UMBRA}" validate "${SCENE}" --image "${exr}" --json
    RESULT_VARIABLE code OUTPUT_VARIABLE report ERROR_VARIABLE err)
  if(NOT code EQUAL 0 AND NOT code EQUAL 1)
    message(FATAL_ERROR "validate of ${variant} exited ${code}\n${err}")
  endif()
  string(JSON lit_${variant} GET "${report}" lights 0 false_lit)
  string(JSON shadowed_${variant} GET "${report}" lights 0 false_shadowed)
  message(STATUS "${variant}: ${lit_${variant}} false lit, ${shadowed_${variant}} false shadowed")
endforeach()

math(EXPR lost "${lit_id} - ${lit_depth}")
if(lost LESS 300 OR NOT shadowed_id EQUAL 0)
  message(FATAL_ERROR "id: ${lit_id} false lit (depth: ${lit_depth}), ${shadowed_id} false shadowed")
endif()
foreach(variant id-polygon post)
  math(EXPR more "${lit_${variant}} + ${shadowed_${variant}} - ${lit_depth} - ${shadowed_depth}")
  if(more GREATER 20)
    message(FATAL_ERROR "${variant}: ${more} more mistakes than the depth map")
  endif()
endforeach()
