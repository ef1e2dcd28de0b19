#!/usr/bin/env bash
# The bash completion (completions/clpost.bash), driven as bash drives it: COMP_WORDS and
# COMP_CWORD set, _clpost called, COMPREPLY compared with the exact expected words. Runs in a
# scratch folder holding known files, so file completions are known too.
#
# Usage: completion_test.sh CLPOST SOURCE_DIR   (ctest: packaging.completion)
set -euo pipefail
bin=$1
src=$(cd "$2" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
unset CLPOST_DATA_DIR
cd "$scratch"
mkdir cl-files out
touch part.cl part.nc lathe5.yaml notes.txt cl-files/a.cl

# shellcheck source=../../completions/clpost.bash
source "$src/completions/clpost.bash"
[ "$(complete -p clpost)" = "complete -F _clpost clpost" ] || {
  echo "completion_test: FAIL: not registered for clpost: $(complete -p clpost)" >&2
  exit 1
}

failures=0
cases=0
# expect "COMMAND LINE|" "WORDS...": the line up to the cursor (| marks it; the cursor is in the
# last word) completes to exactly WORDS (in any order). Words are split as bash splits them.
expect() {
  local line=${1%|} want got
  # bash splits words at '=' too (COMP_WORDBREAKS): --machine=n is "--machine" "=" "n".
  read -ra COMP_WORDS <<<"${line//=/ = }"
  [[ $line == *" " ]] && COMP_WORDS+=("")
  COMP_WORDS[0]=$bin
  COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
  COMPREPLY=()
  _clpost
  want=$(tr ' ' '\n' <<<"$2" | sed '/^$/d' | sort)
  got=$(printf '%s\n' "${COMPREPLY[@]}" | sed '/^$/d' | sort)
  cases=$((cases + 1))
  if [ "$got" != "$want" ]; then
    echo "completion_test: FAIL: '$1' completes to [$(xargs <<<"$got")], expected [$(xargs <<<"$want")]" >&2
    failures=$((failures + 1))
  fi
}

machines="fanuc-0i-t fanuc-0i-tf-live generic-lathe haas-st haas-st-20y heidenhain-pilot linuxcnc-lathe linuxcnc-lathe-c nct-2000t sinumerik-840d"
files="cl-files lathe5.yaml notes.txt out part.cl part.nc"

# Subcommands and inputs.
expect "clpost |" "check cl2apt machines plan plot schema sheet verify $files"
expect "clpost p|" "plan plot part.cl part.nc"
expect "clpost ch|" "check"
expect "clpost cl-files/|" "cl-files/a.cl"
expect "clpost machines |" "diff show"
expect "clpost machines show |" "$machines cl-files lathe5.yaml out"
expect "clpost machines show --|" "--help --set --origin"
expect "clpost machines diff fanuc-0i-t |" "$machines cl-files lathe5.yaml out"
expect "clpost schema --|" "--help --markdown"
expect "clpost cl2apt -|" "-h --help -o --output"
expect "clpost cl2apt |" "$files"
expect "clpost check part.cl |" "$files"
# Options, per command.
expect "clpost --k|" "--keep-going"
expect "clpost --ver|" "--verify --version"
expect "clpost -|" "-h --help --version -m --machine --set -o --output --strict -d --output-dir \
  -r --recursive -j --jobs --keep-going -q --quiet --report --verify --sheet --sheets --date"
expect "clpost sheet -|" "-h --help -m --machine --set -o --output --format --nc --date"
expect "clpost sheet --format |" "html json"
expect "clpost --sheet |" "cl-files out"
expect "clpost check -|" "-h --help -m --machine --set --strict"
expect "clpost plan --|" "--help --machine --set --format"
expect "clpost verify --|" "--help --machine --set --cl --plan --tolerance"
expect "clpost plot -|" "-h --help -m --machine --set --cl -o --output --thread --full"
expect "clpost machines -|" "-h --help"
# An option's value is not taken for a subcommand: `-m plot` is the machine, not the command.
expect "clpost -m plot --s|" "--set --sheet --sheets --strict"
expect "clpost -m fanuc-0i-t plot --t|" "--thread"
# Machine names (from `clpost machines`), machine files and folders.
expect "clpost -m |" "$machines lathe5.yaml cl-files out"
expect "clpost --machine h|" "haas-st haas-st-20y heidenhain-pilot"
expect "clpost verify -m lin|" "linuxcnc-lathe linuxcnc-lathe-c"
expect "clpost -m l|" "linuxcnc-lathe linuxcnc-lathe-c lathe5.yaml"
expect "clpost --machine=n|" "nct-2000t"
expect "clpost plot --machine=|" "$machines lathe5.yaml cl-files out"
# Other option values.
expect "clpost plan --format |" "text json"
expect "clpost plan --format=j|" "json"
expect "clpost -d |" "cl-files out"
expect "clpost -o p|" "part.cl part.nc"
expect "clpost verify part.nc --cl p|" "part.cl part.nc"
expect "clpost --set |" ""
expect "clpost -j |" ""
expect "clpost plot --thread |" ""

echo "completion_test: $cases cases, $failures failures"
[ $failures -eq 0 ]
