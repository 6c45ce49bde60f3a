#!/bin/bash
# Bash completion (cli/umbra-completion.bash) against the real executable:
# verbs, fuzz's commands, a verb's options, an option's choices, and files
# where an option takes a path. Usage: completion_test.sh COMPLETION UMBRA WORK_DIR
set -eu
completion=$1 umbra=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
touch scene.json scenery.glb
# shellcheck source=/dev/null
source "$completion"
# The words of a command line being completed (the last one is the cursor's).
complete_line() {
  COMP_WORDS=("$umbra" "$@")
  COMP_CWORD=$#
  _umbra
  [ ${#COMPREPLY[@]} -eq 0 ] || printf "%s\n" "${COMPREPLY[@]}" | sort | tr "\n" " "
}
expect() {  # EXPECTED WORDS...
  local want=$1 got
  shift
  got=$(complete_line "$@")
  [ "$got" = "$want" ] || { echo "completing '$*': got '$got', want '$want'" >&2; exit 1; }
}
expect "render " ren
expect "footprint fuzz " f
expect "check " fuzz ch
expect "--map-bias --map-dither --map-lookup --map-pcf --map-resolution --map-slope-bias --map-variant --memory-limit --method " render scene.json --m
expect "exact map ray volume " render --method ""
expect "bilinear nearest " render --map-lookup ""
expect "scene.json scenery.glb " render scen
expect "scene.json " render -o scene.j
expect "--seed --shard --summary " fuzz check --s
expect "" render --threads ""
echo "completion: verbs, options, choices and files"
