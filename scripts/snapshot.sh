#!/usr/bin/env bash
# Writes everything clpost says about its inputs into OUTDIR, one file per (command, machine,
# input): the program, its errors and exit status, --verify, the plan (text and JSON), the plot,
# the setup sheet (HTML and JSON), `machines show --origin` of every machine and `schema`. Two
# snapshots of two builds compared with `diff -r` show every byte a change moved: a refactor that
# promises identical output runs it before and after (scripts/snapshot.sh --compare A B).
#
# Inputs: every CL file of samples/, tests/data/, fuzz/seeds/cl/, and the real CAM files in
# ../shared (read in place) when that folder is there.
# Usage: scripts/snapshot.sh OUTDIR [BIN]        (BIN default build/clpost)
#        scripts/snapshot.sh --compare A B       diff two snapshots (exit 1 when they differ)
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = --compare ]; then
  diff -r -q "$2" "$3" && echo "snapshot: identical ($(find "$2" -type f | wc -l) files)"
  exit
fi
out=${1:?usage: scripts/snapshot.sh OUTDIR [BIN]}
bin=$(readlink -f "${2:-build/clpost}")
rm -rf "$out" && mkdir -p "$out"
out=$(readlink -f "$out")

inputs=()
while IFS= read -r f; do inputs+=("$f"); done < <(
  { find samples tests/data fuzz/seeds/cl -type f \( -name '*.apt' -o -name '*.cls' -o -name '*.cl' \
      -o -name '*.ncl' \) 2>/dev/null
    [ -d ../shared ] && find ../shared/realcl ../shared/realcam ../shared/ncl ../shared/multichannel \
      -type f ! -name 'README.md' ! -name '*.NC' ! -name '*.as' 2>/dev/null
  } | sort)
machines=$("$bin" machines | awk '{print $1}')

"$bin" schema >"$out/schema.json" 2>&1 || true
"$bin" machines >"$out/machines.txt" 2>&1 || true
for m in $machines; do
  "$bin" machines show "$m" --origin >"$out/show-$m.txt" 2>&1 || true
done

# One job: every command on one machine and one input. Names: <machine>/<input path with / as %>.
job() {
  local bin=$1 out=$2 m=$3 f=$4 key rc
  key=$(printf '%s' "$f" | sed 's|^\.\./||; s|/|%|g')
  local d="$out/$m" && mkdir -p "$d"
  rc=0; timeout 120 "$bin" -m "$m" "$f" >"$d/$key.post" 2>"$d/$key.post.err" || rc=$?
  echo "$rc" >>"$d/$key.post.err"
  rc=0; timeout 120 "$bin" -m "$m" --verify -o /dev/null "$f" >"$d/$key.verify" 2>&1 || rc=$?
  echo "$rc" >>"$d/$key.verify"
  rc=0; timeout 120 "$bin" plan -m "$m" "$f" >"$d/$key.plan" 2>&1 || rc=$?
  echo "$rc" >>"$d/$key.plan"
  rc=0; timeout 120 "$bin" plan -m "$m" --format json "$f" >"$d/$key.plan.json" 2>&1 || rc=$?
  echo "$rc" >>"$d/$key.plan.json"
  rc=0; timeout 120 "$bin" plot -m "$m" "$f" >"$d/$key.svg" 2>&1 || rc=$?
  echo "$rc" >>"$d/$key.svg"
  rc=0; timeout 120 "$bin" sheet -m "$m" --date 2026-01-01 "$f" >"$d/$key.html" 2>&1 || rc=$?
  echo "$rc" >>"$d/$key.html"
  rc=0; timeout 120 "$bin" sheet -m "$m" --date 2026-01-01 --format json "$f" >"$d/$key.json" 2>&1 || rc=$?
  echo "$rc" >>"$d/$key.json"
}
export -f job
for m in $machines; do
  for f in "${inputs[@]}"; do printf '%s\0%s\0' "$m" "$f"; done
done | xargs -0 -n 2 -P "${SNAPSHOT_JOBS:-2}" bash -c 'job "$0" "$1" "$2" "$3"' "$bin" "$out"
echo "snapshot: $(find "$out" -type f | wc -l) files in $out"
