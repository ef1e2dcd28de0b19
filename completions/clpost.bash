# bash completion for clpost                                    -*- shell-script -*-
# Installed as share/bash-completion/completions/clpost (bash-completion loads it on first use);
# or `source completions/clpost.bash` by hand. Needs nothing but bash.
#
# Completes subcommands, each command's options, shipped machine names after -m/--machine
# (asked from the clpost being completed: `clpost machines`), and files.
#
# To add a subcommand: add its name to the post line of _clpost_subcommands_of (a subcommand of
# machines, such as `machines show`, to its machines line), its options to _clpost_options (as
# "machines show" for a nested one), any option that takes a value to _clpost_value_options (and
# what to offer for it to _clpost_complete_value), and what its positional arguments are to
# _clpost_positionals. tests/packaging/cli_surface_test.sh checks that the subcommands and
# options offered are exactly those `clpost ... --help` lists, for every command.

# Subcommands of clpost and of each subcommand (nested ones as "machines show").
_clpost_subcommands_of() {
  case $1 in
    post) echo "check cl2apt machines plan plot schema sheet verify" ;;
    machines) echo "diff show" ;;
  esac
}

# The options of a command ("post" is clpost without a subcommand).
_clpost_options() {
  local machine="-m --machine --set"
  case $1 in
    post)
      echo "-h --help --version $machine -o --output --strict -d --output-dir -r --recursive" \
        "-j --jobs --keep-going -q --quiet --report --verify --sheet --sheets --date"
      ;;
    check) echo "-h --help $machine --strict" ;;
    plan) echo "-h --help $machine --format" ;;
    verify) echo "-h --help $machine --cl --plan --tolerance" ;;
    plot) echo "-h --help $machine --cl -o --output --thread --full" ;;
    sheet) echo "-h --help $machine -o --output --format --nc --date" ;;
    machines | "machines diff") echo "-h --help" ;;
    "machines show") echo "-h --help --set --origin" ;;
    schema) echo "-h --help --markdown" ;;
    cl2apt) echo "-h --help -o --output" ;;
  esac
}

# What a command's positional arguments are: files (CL files, NC programs), machines (names
# or machine files), or none.
_clpost_positionals() {
  case $1 in
    machines | schema) echo none ;;
    "machines show" | "machines diff") echo machines ;;
    *) echo files ;;
  esac
}

# Options that take a value (the next word is the value, not a command or an input).
_clpost_value_options="-m --machine --set -o --output -d --output-dir -j --jobs --report --format
  --cl --plan --tolerance --thread --sheet --nc --date"

# The shipped machine names: the first column of `clpost machines`, from the clpost being
# completed (so build/clpost offers its own source tree's machines and $CLPOST_DATA_DIR counts).
_clpost_machine_names() {
  local bin=$1
  # shellcheck disable=SC2088  # a literal "~/" typed on the command line
  [[ $bin == "~/"* ]] && bin=$HOME/${bin#"~/"}
  "$bin" machines 2>/dev/null | while read -r name _; do printf '%s\n' "$name"; done
}

# Appends to COMPREPLY the machine names and machine files (*.yaml, and folders) matching $1.
_clpost_machines() {
  local name
  while IFS= read -r name; do COMPREPLY+=("$name"); done \
    < <(compgen -W "$(_clpost_machine_names "${COMP_WORDS[0]}")" -- "$1")
  _clpost_files "$1" "*.yaml"
}

# Appends to COMPREPLY the files and directories whose names start with $1; $2: a glob that
# files (not directories) must match.
_clpost_files() {
  local f
  compopt -o filenames 2>/dev/null || :
  while IFS= read -r f; do
    # shellcheck disable=SC2053  # $2 is a glob
    if [[ -d $f || -z ${2:-} || $f == $2 ]]; then COMPREPLY+=("$f"); fi
  done < <(compgen -f -- "$1")
}

# The value of option $1, the word being completed being $2.
_clpost_complete_value() {
  local opt=$1 cur=$2
  case $opt in
    -m | --machine) _clpost_machines "$cur" ;;
    --format)
      local formats="text json"
      [[ $command == sheet ]] && formats="html json"
      mapfile -t COMPREPLY < <(compgen -W "$formats" -- "$cur")
      ;;
    -d | --output-dir | --sheet)
      compopt -o filenames 2>/dev/null || :
      mapfile -t COMPREPLY < <(compgen -d -- "$cur")
      ;;
    -o | --output | --report | --cl | --plan | --nc) _clpost_files "$cur" ;;
    *) ;;  # --set KEY=VALUE, -j, --tolerance, --thread, --date: nothing to offer
  esac
}

_clpost() {
  COMPREPLY=()
  local cword=$COMP_CWORD cur=${COMP_WORDS[COMP_CWORD]} prev=""
  ((cword > 0)) && prev=${COMP_WORDS[cword - 1]}
  # `--opt=value`: bash splits the word at '=' (COMP_WORDBREAKS).
  if [[ $cur == "=" ]]; then
    cur=""
  elif [[ $prev == "=" ]] && ((cword > 1)); then
    prev=${COMP_WORDS[cword - 2]}
  fi

  # The command path: words that name a subcommand of the command so far, skipping options,
  # their values and inputs.
  local command=post i word
  for ((i = 1; i < cword; i++)); do
    word=${COMP_WORDS[i]}
    if [[ " $_clpost_value_options " == *[[:space:]]"$word"[[:space:]]* ]]; then
      ((i++))
      [[ ${COMP_WORDS[i]:-} == "=" ]] && ((i++))
    elif [[ -n $word && $word != -* && " $(_clpost_subcommands_of "$command") " == *" $word "* ]]; then
      [[ $command == post ]] && command=$word || command="$command $word"
    fi
  done

  if [[ " $_clpost_value_options " == *[[:space:]]"$prev"[[:space:]]* ]]; then
    _clpost_complete_value "$prev" "$cur"
    return 0
  fi
  if [[ $cur == -* ]]; then
    mapfile -t COMPREPLY < <(compgen -W "$(_clpost_options "$command")" -- "$cur")
    return 0
  fi
  mapfile -t COMPREPLY < <(compgen -W "$(_clpost_subcommands_of "$command")" -- "$cur")
  case $(_clpost_positionals "$command") in
    files) _clpost_files "$cur" ;;
    machines) _clpost_machines "$cur" ;;
  esac
  return 0
}

complete -F _clpost clpost
