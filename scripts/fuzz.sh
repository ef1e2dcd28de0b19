#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan, in build-fuzz/) and runs each for SECONDS
# (default 60), one job at a time, printing how many inputs each one ran. Exits 1 on the first
# crash, leak, timeout (> 1 s for one input) or out-of-memory (> 2 GB); the input that did it is
# left in build-fuzz/artifacts/ and the fuzzer's log in build-fuzz/logs/.
#
# Usage: scripts/fuzz.sh [--round-trip] [SECONDS | --runs N] [TARGET...]
#        scripts/fuzz.sh --oracle [SECONDS]
#   targets: cl_post_fuzzer cldata_fuzzer machine_yaml_fuzzer nc_verify_fuzzer
#   --runs N: run each target for N inputs instead of a time (e.g. --runs 1000000).
#   --round-trip: cl_post_fuzzer also posts on every shipped machine and verifies the program
#     against the CL; a clean post that does not verify stops the run (a bug in the post or in
#     verify). Not in CI's smoke run: a hunt, run for as long as there is time.
#   --oracle: the oracle's differential test (tests/oracle/, docs/cl-meaning.md) on fresh seeds
#     for SECONDS (default 60) on each control in turn: random lathe programs posted on
#     linuxcnc-lathe and run through LinuxCNC's rs274, and posted on fanuc-0i-t, haas-st,
#     heidenhain-pilot, nct-2000t and sinumerik-840d and read by the oracle's readers of their
#     documented meanings, with block delete off and on, every event compared with the model of
#     what the CL means. Builds build/ (Release, the tests' build) rather than build-fuzz/; prints for each control the count, the classes of
#     difference with their first seed, the refusals, and the first program that differs in full
#     (any other: build/tests/oracle_run --control C --seed N). Exit status 1 when one differs.
#
# ASan keeps 5 frames of allocation stack and a 32 MB quarantine unless ASAN_OPTIONS says
# otherwise: the same checks, with shorter allocation stacks in reports and a fifth of the memory.
#
# Each target's corpus grows in build-fuzz/corpus/<target>/ from run to run. Seeds are made fresh
# every run from samples/, fuzz/seeds/, the shipped machines and posts, and the real CAM files in
# ../shared/realcl/ when that folder is there (read in place, never copied into the tree).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = --oracle ]; then
  seconds=${2:-60}
  case "$seconds" in '' | *[!0-9]*) echo "fuzz.sh: --oracle takes a number of seconds" >&2; exit 2 ;; esac
  build=${CLPOST_ORACLE_BUILD:-build}
  scripts/deps.sh test
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" -j "$(nproc)" --target oracle_run
  status=0
  for control in linuxcnc fanuc haas heidenhain nct sinumerik; do
    echo "== oracle on $control: fresh seeds for $seconds s"
    "$build/tests/oracle_run" --control "$control" --seconds "$seconds" || status=1
  done
  exit "$status"
fi
if [ "${1:-}" = --round-trip ]; then
  export CLPOST_FUZZ_ROUND_TRIP=1
  shift
fi
limit=(-max_total_time=60)
what="60 s"
if [ "${1:-}" = --runs ]; then
  [ -n "${2:-}" ] || { echo "fuzz.sh: --runs needs a count" >&2; exit 2; }
  limit=(-runs="$2")
  what="$2 inputs"
  shift 2
elif [ $# -gt 0 ]; then
  limit=(-max_total_time="$1")
  what="$1 s"
  shift
fi
export ASAN_OPTIONS=${ASAN_OPTIONS:-malloc_context_size=5:quarantine_size_mb=32}
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(cl_post_fuzzer cldata_fuzzer machine_yaml_fuzzer nc_verify_fuzzer)
build=${CLPOST_FUZZ_BUILD:-build-fuzz}

scripts/deps.sh test
cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCLPOST_FUZZ=ON -DCLPOST_TESTS=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target "${targets[@]}"

# Seeds: small files only (libFuzzer cuts inputs to -max_len anyway).
seed() {  # seed <target> <files...>
  local dir="$build/seeds/$1"
  shift
  rm -rf "$dir"
  mkdir -p "$dir"
  local f
  for f in "$@"; do
    [ -f "$f" ] && [ "$(stat -c %s "$f")" -le 65536 ] || continue
    cp "$f" "$dir/$(printf '%s' "$f" | tr '/ ' '__')"
  done
}
realcl=()
if [ -d ../shared/realcl ]; then
  while IFS= read -r -d '' f; do realcl+=("$f"); done \
    < <(find ../shared/realcl -type f ! -name '*.md' -print0)
fi
mapfile -t samples < <(find samples -type f \( -name "*.apt" -o -name "*.cls" -o -name "*.ncl" \) | sort)
seed cl_post_fuzzer "${samples[@]}" fuzz/seeds/cl/* "${realcl[@]}"
realcam_bin=()
[ -f ../shared/realcam/apt360_binary/cl.tap ] && realcam_bin+=(../shared/realcam/apt360_binary/cl.tap)
seed cldata_fuzzer fuzz/seeds/cldata/* "${realcam_bin[@]}"
seed machine_yaml_fuzzer machines/*.yaml posts/*.yaml fuzz/seeds/yaml/*
mapfile -t goldens < <(find samples/golden -type f | sort)
seed nc_verify_fuzzer "${goldens[@]}"

mkdir -p "$build/artifacts" "$build/logs"
status=0
summary=""
for t in "${targets[@]}"; do
  case "$t" in
    cl_post_fuzzer) dict=fuzz/cl.dict ;;
    cldata_fuzzer) dict=fuzz/cldata.dict ;;
    machine_yaml_fuzzer) dict=fuzz/yaml.dict ;;
    nc_verify_fuzzer) dict=fuzz/nc.dict ;;
    *) echo "fuzz.sh: unknown target '$t'" >&2; exit 2 ;;
  esac
  corpus="$build/corpus/$t"
  log="$build/logs/$t.log"
  mkdir -p "$corpus"
  echo "== $t: $what"
  rc=0
  "$build/fuzz/$t" "$corpus" "$build/seeds/$t" -dict="$dict" "${limit[@]}" \
    -timeout=1 -rss_limit_mb=2048 -max_len=4096 -print_final_stats=1 \
    -artifact_prefix="$build/artifacts/$t-" >"$log" 2>&1 || rc=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  cov=$(grep -E '^#[0-9]+' "$log" | tail -1 | sed -n 's/.* cov: \([0-9]*\).*/\1/p')
  line="$t: ${runs:-?} executions ($what), coverage ${cov:-?} edges, corpus $(ls "$corpus" | wc -l) files"
  if [ "$rc" -ne 0 ]; then
    line="$line: FAILED (exit $rc, log $log)"
    status=1
    grep -E 'ERROR: |SUMMARY: |Test unit written to|runtime error' "$log" | head -20 >&2 || true
  fi
  echo "$line"
  summary+="$line"$'\n'
done
echo "== fuzz summary"
printf '%s' "$summary"
exit $status
