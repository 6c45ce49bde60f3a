# Bash completion for umbra (docs/cli.md "Shell completion"). Verbs and
# fuzz's commands are listed here; every verb's options, their choices and
# whether they take a file are read from `umbra VERB --help` when Tab is
# pressed (~10 ms: --help loads no image library), so they follow the
# executable that is completed.
#   source build/share/bash-completion/completions/umbra

# The option names and value types of a help text: "NAME TYPE" lines, TYPE
# "-" for a flag.
_umbra_options() {
  local line names type
  while IFS= read -r line; do
    [[ $line =~ ^\ +(-[A-Za-z0-9],)?(--[a-z0-9-]+)(\ ([A-Z][A-Za-z0-9_.]*(:[^ ]*)?))? ]] || continue
    names=${BASH_REMATCH[2]} type=${BASH_REMATCH[4]:--}
    # "Excludes:" and "Needs:" are CLI11's notes, not value types.
    [[ $type == Excludes:* || $type == Needs:* ]] && type=-
    [[ -n ${BASH_REMATCH[1]} ]] && printf '%s %s\n' "${BASH_REMATCH[1]%,}" "$type"
    printf '%s %s\n' "$names" "$type"
  done
}

_umbra() {
  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD - 1]}
  local umbra=${COMP_WORDS[0]} verb="" sub="" i
  for ((i = 1; i < COMP_CWORD; i++)); do
    [[ ${COMP_WORDS[i]} == -* ]] && continue
    if [[ -z $verb ]]; then
      verb=${COMP_WORDS[i]}
    elif [[ $verb == fuzz && -z $sub ]]; then
      sub=${COMP_WORDS[i]}
    fi
  done
  COMPREPLY=()
  if [[ -z $verb ]]; then
    mapfile -t COMPREPLY < <(compgen -W "render validate volume footprint sunlight merge batch fuzz --help --version" -- "$cur")
    return
  fi
  if [[ $verb == fuzz && -z $sub ]]; then
    mapfile -t COMPREPLY < <(compgen -W "check export real merge --help" -- "$cur")
    return
  fi
  local options command=("$umbra" "$verb")
  [[ -n $sub ]] && command+=("$sub")
  options=$("${command[@]}" --help 2> /dev/null | _umbra_options)
  # The value of the option just typed: its choices, a file, or nothing.
  if [[ $prev == -* ]]; then
    local type
    type=$(awk -v o="$prev" '$1 == o { print $2; exit }' <<< "$options")
    if [[ -n $type && $type != - ]]; then
      if [[ $type =~ \{([^}]*)\} ]]; then
        mapfile -t COMPREPLY < <(compgen -W "${BASH_REMATCH[1]//,/ }" -- "$cur")
      elif [[ $type =~ FILE|PATH|DIR|OUT|SCENE|MANIFEST|PART ]]; then
        mapfile -t COMPREPLY < <(compgen -f -- "$cur")
        compopt -o filenames 2> /dev/null
      fi
      return
    fi
  fi
  if [[ $cur == -* ]]; then
    mapfile -t COMPREPLY < <(compgen -W "$(awk '{ print $1 }' <<< "$options")" -- "$cur")
  else
    mapfile -t COMPREPLY < <(compgen -f -- "$cur")
    compopt -o filenames 2> /dev/null
  fi
}
complete -F _umbra umbra
