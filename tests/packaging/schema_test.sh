#!/usr/bin/env bash
# The JSON Schema of machine and post files: schema/clpost-machine.schema.json (what every shipped
# file names in its first line) is what `clpost schema` prints now, and a real JSON Schema
# validator (Debian's python3-jsonschema, draft 2020-12) accepts every shipped machine and post
# and rejects a file with a misspelt key, a value of the wrong type and an unknown template.
#
# Usage: schema_test.sh CLPOST SOURCE_DIR   (ctest: packaging.schema; needs python3-jsonschema,
# python3-yaml, installed by scripts/deps.sh test)
set -euo pipefail
bin=$1
src=$(cd "$2" && pwd)
failures=0
fail() {
  echo "schema_test: FAIL: $*" >&2
  failures=$((failures + 1))
}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

"$bin" schema >"$scratch/schema.json"
cmp -s "$scratch/schema.json" "$src/schema/clpost-machine.schema.json" ||
  fail "schema/clpost-machine.schema.json is stale: run 'build/clpost schema > schema/clpost-machine.schema.json'"

# validate SCHEMA FILE...: one line per file, "ok FILE" or "invalid FILE: path: message".
validate() {
  /usr/bin/python3 - "$@" <<'PY'
import json, sys
import jsonschema, yaml
schema = json.load(open(sys.argv[1]))
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)
for path in sys.argv[2:]:
    errors = sorted(validator.iter_errors(yaml.safe_load(open(path)) or {}), key=str)
    if errors:
        e = errors[0]
        where = "/".join(str(p) for p in e.absolute_path)
        print(f"invalid {path}: {where}: {e.message}")
    else:
        print(f"ok {path}")
PY
}

shipped=("$src"/machines/*.yaml "$src"/posts/*.yaml)
while read -r status file rest; do
  [ "$status" = ok ] || fail "a shipped file does not validate: $file $rest"
done < <(validate "$scratch/schema.json" "${shipped[@]}")
[ "${#shipped[@]}" -ge 14 ] || fail "expected the 7 machines and 7 posts, found ${#shipped[@]} files"

# Files the schema must refuse, each for its own reason.
printf 'extends: fanuc-lathe\nlimits:\n  max_rmp: 3000\n' >"$scratch/misspelt-key.yaml"
printf 'extends: fanuc-lathe\nlimits:\n  max_rpm: fast\n' >"$scratch/wrong-type.yaml"
printf 'extends: fanuc-lathe\nthreading:\n  strategy: cycel\n' >"$scratch/bad-choice.yaml"
printf 'extends: fanuc-lathe\ntemplates:\n  tool_chnage: ["T{tool}"]\n' >"$scratch/unknown-template.yaml"
printf 'extends: fanuc-lathe\ntemplates:\n  tool_change: ["T{tol}"]\n' >"$scratch/unknown-field.yaml"
while read -r status file rest; do
  [ "$status" = invalid ] || fail "the schema accepts $(basename "$file")"
done < <(validate "$scratch/schema.json" "$scratch"/misspelt-key.yaml "$scratch"/wrong-type.yaml \
  "$scratch"/bad-choice.yaml "$scratch"/unknown-template.yaml "$scratch"/unknown-field.yaml)

# The same files are what clpost itself refuses when it loads them (exit 2).
for f in misspelt-key wrong-type bad-choice unknown-template unknown-field; do
  set +e
  "$bin" machines show "$scratch/$f.yaml" >/dev/null 2>&1
  rc=$?
  set -e
  [ "$rc" -eq 2 ] || fail "clpost loads $f.yaml (exit $rc, expected 2)"
done

if [ "$failures" -gt 0 ]; then
  echo "schema_test: $failures failures" >&2
  exit 1
fi
echo "schema_test: ok (${#shipped[@]} shipped files valid, 5 bad files refused)"
