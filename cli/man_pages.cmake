# The man pages, written at build time from the executable's own --help by
# help2man (Debian's help2man): umbra.1, and umbra-VERB.1 for every verb, so
# that they never disagree with the options. Run by cli/CMakeLists.txt:
#   cmake -DUMBRA=<exe> -DHELP2MAN=<help2man> -DOUT_DIR=<dir> -DVERBS="a;b" -P man_pages.cmake
cmake_minimum_required(VERSION 3.25)
foreach(var UMBRA HELP2MAN OUT_DIR VERBS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "man_pages.cmake: ${var} is not set")
  endif()
endforeach()
file(MAKE_DIRECTORY "${OUT_DIR}")
# The same bytes on every build: help2man dates the page by SOURCE_DATE_EPOCH.
set(ENV{SOURCE_DATE_EPOCH} 1767225600)  # 2026-01-01
set(see_also "${OUT_DIR}/see-also.h2m")
set(pages "umbra(1)")
foreach(verb IN LISTS VERBS)
  string(APPEND pages ", umbra-${verb}(1)")
endforeach()
file(WRITE "${see_also}" "[SEE ALSO]\n${pages}.\nThe documentation in docs/ of umbra's source: cli.md has every verb, option, output and exit code.\n")

function(page output help_option name)
  execute_process(
    COMMAND "${HELP2MAN}" --no-info --no-discard-stderr --name=${name}
      "--help-option=${help_option}" --version-option=--version --include "${see_also}"
      --output "${output}.tmp" "${UMBRA}"
    RESULT_VARIABLE code ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "help2man ${help_option}: ${err}")
  endif()
endfunction()

page("${OUT_DIR}/umbra.1" --help "exact shadow volumes, rendered and proved right")
file(RENAME "${OUT_DIR}/umbra.1.tmp" "${OUT_DIR}/umbra.1")
foreach(verb IN LISTS VERBS)
  set(out "${OUT_DIR}/umbra-${verb}.1")
  execute_process(COMMAND "${UMBRA}" ${verb} --help OUTPUT_VARIABLE help RESULT_VARIABLE code)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "umbra ${verb} --help exited ${code}")
  endif()
  # The page's NAME line: the verb's one-line description (--help's first).
  string(REGEX MATCH "^[^\n]*" summary "${help}")
  string(REGEX REPLACE "^umbra fuzz: " "" summary "${summary}")
  page("${out}" "${verb} --help" "${summary}")
  # help2man names the page after the program: umbra-VERB's own title and NAME.
  file(READ "${out}.tmp" text)
  string(TOUPPER "umbra-${verb}" title)
  string(REGEX REPLACE "\\.TH UMBRA " ".TH ${title} " text "${text}")
  string(REGEX REPLACE "\\.SH NAME\numbra \\\\-" ".SH NAME\numbra-${verb} \\\\-" text "${text}")
  file(WRITE "${out}" "${text}")
  file(REMOVE "${out}.tmp")
endforeach()
