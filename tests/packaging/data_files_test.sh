#!/usr/bin/env bash
# Every shipped machine and post starts with the line that tells editors with YAML support
# (yaml-language-server) which JSON Schema checks it, and the path it names, relative to the
# file, is the schema beside machines/ and posts/ in the source tree and under
# <prefix>/share/clpost (docs/machines.md, "Checking a machine file in an editor").
#
# Usage: data_files_test.sh SOURCE_DIR   (ctest: packaging.data_files)
set -euo pipefail
src=$(cd "$1" && pwd)
# shellcheck disable=SC2016  # a literal $schema
line='# yaml-language-server: $schema=../schema/clpost-machine.schema.json'
failures=0
count=0
for f in "$src"/machines/*.yaml "$src"/posts/*.yaml; do
  count=$((count + 1))
  first=$(head -n 1 "$f")
  if [ "$first" != "$line" ]; then
    echo "data_files_test: FAIL: ${f#"$src"/} starts with '$first', not '$line'" >&2
    failures=$((failures + 1))
  fi
done
# Once the schema is in the tree (clpost schema), the line must lead to it.
if [ -d "$src/schema" ] && [ ! -f "$src/machines/../schema/clpost-machine.schema.json" ]; then
  echo "data_files_test: FAIL: schema/ holds no clpost-machine.schema.json" >&2
  failures=$((failures + 1))
fi
echo "data_files_test: $count files, $failures failures"
[ $failures -eq 0 ]
