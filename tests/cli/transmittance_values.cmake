# Renders a scene with transmittance and reads light LIGHT's
# transmittance.<i>.R/G/B back with OpenImageIO's oiiotool (a reader that is
# not umbra's), counting the pixels that hold each hand-worked τ exactly:
#   cmake -DUMBRA=<exe> -DOIIOTOOL=<exe> -DSCENE=<json> -DWORK_DIR=<dir>
#         -DMETHOD=<method> -DLIGHT=<i> "-DEXPECT=r g b=min;..." -P transmittance_values.cmake
# Fails unless every listed value, written with 9 decimals as oiiotool
# prints it (0.375000000), is held by at least `min` pixels.
cmake_minimum_required(VERSION 3.25)

foreach(var UMBRA OIIOTOOL SCENE WORK_DIR METHOD LIGHT EXPECT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "transmittance_values.cmake: ${var} is not set")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(exr "${WORK_DIR}/render.exr")
execute_process(COMMAND "${UMBRA}" render "${SCENE}" -o "${exr}" --method "${METHOD}" -q
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "render exited ${code}\n${out}\n${err}")
endif()

set(tau "${WORK_DIR}/tau.exr")
execute_process(COMMAND "${OIIOTOOL}" "${exr}"
  --ch "transmittance.${LIGHT}.R,transmittance.${LIGHT}.G,transmittance.${LIGHT}.B" -o "${tau}"
  RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "oiiotool found no transmittance.${LIGHT}.R/G/B:\n${err}")
endif()
execute_process(COMMAND "${OIIOTOOL}" --info --dumpdata "${tau}"
  RESULT_VARIABLE code OUTPUT_VARIABLE dump ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "oiiotool --dumpdata exited ${code}\n${err}")
endif()

foreach(entry IN LISTS EXPECT)
  string(REPLACE "=" ";" parts "${entry}")
  list(GET parts 0 value)
  list(GET parts 1 least)
  string(REPLACE " " ";" rgb "${value}")
  set(pattern ":")
  foreach(c IN LISTS rgb)
    string(REPLACE "." "\\." c "${c}")
    string(APPEND pattern " ${c}")
  endforeach()
  string(REGEX MATCHALL "Pixel \\([0-9]+, [0-9]+\\)${pattern}\n" hits "${dump}")
  list(LENGTH hits n)
  if(n LESS least)
    message(FATAL_ERROR "τ = (${value}) in ${n} pixels, expected at least ${least}")
  endif()
  message(STATUS "τ = (${value}): ${n} pixels")
endforeach()
