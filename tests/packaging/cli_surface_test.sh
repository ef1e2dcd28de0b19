#!/usr/bin/env bash
# The man page and the bash completion cover the command line as it is: every subcommand and
# every option that `clpost [COMMAND...] --help` lists (CLI11, walked recursively) is described
# in docs/clpost.1, and the completion offers exactly those subcommands and options for each
# command. The page renders without a groff warning and carries clpost's version.
#
# Usage: cli_surface_test.sh CLPOST SOURCE_DIR   (ctest: packaging.cli_surface; needs groff-base)
set -euo pipefail
bin=$1
src=$(cd "$2" && pwd)
page=$src/docs/clpost.1
failures=0
fail() {
  echo "cli_surface_test: FAIL: $*" >&2
  failures=$((failures + 1))
}

# help_section TEXT TITLE: the lines of "TITLE:" up to the next blank line.
help_section() { sed -n "/^$2:\$/,/^\$/p" <<<"$1" | sed '1d;/^$/d'; }
# The long and short options of a help text, one a line, sorted.
help_options() {
  help_section "$1" Options | sed -n 's/^  \(-[[:alnum:]],\)\{0,1\}\(--[[:alnum:]-]*\).*/\1\2/p' |
    tr ',' '\n' | sort
}
help_subcommands() { help_section "$1" Subcommands | sed -n 's/^  \([[:alnum:]-]*\) .*/\1/p' | sort; }

# The rendered page, as plain ASCII text (bold and underline removed).
warnings=$(groff -man -Tutf8 -ww -z "$page" 2>&1)
[ -z "$warnings" ] || fail "groff warns on docs/clpost.1: $warnings"
text=$(groff -man -Tascii -P-cbou "$page" 2>/dev/null)
options_text=$(sed -n '/^OPTIONS$/,/^EXIT STATUS$/p' <<<"$text")
commands_text=$(sed -n '/^COMMANDS$/,/^OPTIONS$/p' <<<"$text")
version=$("$bin" --version)
grep -q "^\.TH CLPOST 1 \"[0-9-]*\" \"$version\"" "$page" ||
  fail "docs/clpost.1 .TH does not name '$version'"

# shellcheck source=../../completions/clpost.bash
source "$src/completions/clpost.bash"
# complete WORD...: COMPREPLY for the command line "WORD... <cursor on the last word>", sorted.
complete_words() {
  COMP_WORDS=("$bin" "$@")
  COMP_CWORD=$#
  _clpost
  printf '%s\n' "${COMPREPLY[@]}" | sort
}

commands_checked=0
options_checked=0
# check_command WORD...: the command `clpost WORD...` and, recursively, its subcommands.
check_command() {
  local help name key=${*:-post}
  help=$("$bin" "$@" --help)
  local opts subs
  opts=$(help_options "$help")
  subs=$(help_subcommands "$help")
  commands_checked=$((commands_checked + 1))
  if [ $# -gt 0 ]; then
    grep -Eq "^   clpost $*( |\$)" <<<"$commands_text" ||
      fail "docs/clpost.1 COMMANDS has no 'clpost $*' section"
  fi
  for name in $opts; do
    options_checked=$((options_checked + 1))
    # A tag line: "       -o, --output file", "       --set key=value".
    grep -Eq "^       ($name|-[[:alnum:]], $name|$name, --[[:alnum:]-]+)( |\$)" <<<"$options_text" ||
      fail "docs/clpost.1 OPTIONS does not describe $name (of clpost $key)"
  done
  [ "$(complete_words "$@" -)" = "$opts" ] ||
    fail "completion of 'clpost $* -' is [$(complete_words "$@" - | xargs)], --help: [$(xargs <<<"$opts")]"
  [ "$(_clpost_subcommands_of "$key" | tr ' ' '\n' | sed '/^$/d' | sort)" = "$subs" ] ||
    fail "completion knows subcommands [$(_clpost_subcommands_of "$key")] of 'clpost $*', --help: [$(xargs <<<"$subs")]"
  for name in $subs; do check_command "$@" "$name"; done
}
check_command

echo "cli_surface_test: $commands_checked commands, $options_checked options checked, $failures failures"
[ $failures -eq 0 ]
