# Runs the umbra executable once and checks what a user would see:
#   cmake -DUMBRA=<exe> -DWORK_DIR=<dir> -DARGS=<a|b|c> -DEXPECT_EXIT=<n>
#         [-DSTDOUT_REGEX=<re>] [-DSTDERR_REGEX=<re>] [-DSETUP_FILES=<f|g>]
#         [-DMUST_NOT_EXIST=<p|q>] [-DMUST_EXIST=<p|q>] -P run_umbra.cmake
# WORK_DIR is emptied first and is the working directory of the command;
# SETUP_FILES are created there (empty) beforehand; MUST_NOT_EXIST paths are
# relative to it and checked afterwards (no partial output left behind);
# MUST_EXIST paths likewise (the outputs a successful run promises).
# Lists use '|' because ';' does not survive add_test's argument passing.
# An ARGS element @EMPTY@ is passed as one empty argument (`-o ""`), which
# a CMake list cannot hold. COPY_FILES (absolute paths) are copied into
# WORK_DIR beforehand.
cmake_minimum_required(VERSION 3.25)

foreach(var UMBRA WORK_DIR EXPECT_EXIT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_umbra.cmake: ${var} is not set")
  endif()
endforeach()

string(REPLACE "|" ";" args "${ARGS}")
string(REPLACE "|" ";" setup_files "${SETUP_FILES}")
string(REPLACE "|" ";" must_not_exist "${MUST_NOT_EXIST}")
string(REPLACE "|" ";" must_exist "${MUST_EXIST}")

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
foreach(f IN LISTS setup_files)
  file(WRITE "${WORK_DIR}/${f}" "")
endforeach()
string(REPLACE "|" ";" copy_files "${COPY_FILES}")
foreach(f IN LISTS copy_files)
  file(COPY "${f}" DESTINATION "${WORK_DIR}")
endforeach()

list(FIND args "@EMPTY@" empty_at)
if(empty_at GREATER_EQUAL 0)
  list(SUBLIST args 0 ${empty_at} args_before)
  math(EXPR after_at "${empty_at} + 1")
  set(args_after "")
  list(LENGTH args n_args)
  if(after_at LESS n_args)
    list(SUBLIST args ${after_at} -1 args_after)
  endif()
  execute_process(
    COMMAND "${UMBRA}" ${args_before} "" ${args_after}
    WORKING_DIRECTORY "${WORK_DIR}"
    RESULT_VARIABLE exit_code
    OUTPUT_VARIABLE out
    ERROR_VARIABLE err)
else()
  execute_process(
    COMMAND "${UMBRA}" ${args}
    WORKING_DIRECTORY "${WORK_DIR}"
    RESULT_VARIABLE exit_code
    OUTPUT_VARIABLE out
    ERROR_VARIABLE err)
endif()

set(failures "")
if(NOT exit_code STREQUAL "${EXPECT_EXIT}")
  string(APPEND failures "exit code ${exit_code}, expected ${EXPECT_EXIT}\n")
endif()
if(DEFINED STDOUT_REGEX AND NOT STDOUT_REGEX STREQUAL "" AND NOT out MATCHES "${STDOUT_REGEX}")
  string(APPEND failures "stdout does not match '${STDOUT_REGEX}'\n")
endif()
if(DEFINED STDERR_REGEX AND NOT STDERR_REGEX STREQUAL "" AND NOT err MATCHES "${STDERR_REGEX}")
  string(APPEND failures "stderr does not match '${STDERR_REGEX}'\n")
endif()
foreach(p IN LISTS must_not_exist)
  if(EXISTS "${WORK_DIR}/${p}")
    string(APPEND failures "'${p}' exists but must not\n")
  endif()
endforeach()
foreach(p IN LISTS must_exist)
  if(NOT EXISTS "${WORK_DIR}/${p}")
    string(APPEND failures "'${p}' does not exist but must\n")
  endif()
endforeach()

if(failures)
  message(FATAL_ERROR "umbra ${args}\n--- stdout:\n${out}\n--- stderr:\n${err}\n--- failures:\n${failures}")
endif()
message(STATUS "umbra ${args}: exit ${exit_code} as expected")
