#!/usr/bin/env bash
# Memory and time at scale (issue #26): post, --verify and plot on three generated files (1 M and
# 2 M GOTOs, 3000 identical multi-pass threads) on generic-lathe, next to the naive GOTO-to-G1
# loop (bench/naive_goto.cc) that post's CPU time is measured against. Prints, for each, the wall
# time, the CPU time (user+sys) and the peak RSS (GNU time), best of RUNS runs by wall time;
# then the ratios the issue asks: post CPU / naive CPU, verify and plot time / post time, and
# verify's RSS at 2 M over its RSS at 1 M.
#
#   bench/scale.sh            RUNS=1 BUILD=build-release DATA=$TMPDIR/clpost-bench
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD:-$root/build-release}
data=${DATA:-${TMPDIR:-/tmp}/clpost-bench}
runs=${RUNS:-1}
machine=generic-lathe

[ -x /usr/bin/time ] || "$root/scripts/deps.sh" bench
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCLPOST_TESTS=OFF >/dev/null
fi
cmake --build "$build" --target clpost gen_cl naive_goto >/dev/null

mkdir -p "$data"
declare -A files=([1M]=$data/large-1000000.cl [2M]=$data/large-2000000.cl
  [threads]=$data/threads-3000.cl)
[ -s "${files[1M]}" ] || "$build/bench/gen_cl" large "${files[1M]}" 1000000
[ -s "${files[2M]}" ] || "$build/bench/gen_cl" large "${files[2M]}" 2000000
[ -s "${files[threads]}" ] || "$build/bench/gen_cl" threads "${files[threads]}" 3000
out=$data/scale-out
rm -rf "$out" && mkdir -p "$out"

# measure NAME CMD...: runs CMD $runs times, keeps the fastest (wall) "wall cpu rss_mb" in
# result[NAME] and prints it.
declare -A result
measure() {
  local name=$1 best="" stats line
  shift
  stats=$(mktemp)
  for _ in $(seq "$runs"); do
    /usr/bin/time -o "$stats" -f '%e %U %S %M' "$@" >/dev/null 2>"$out/stderr" ||
      { echo "$name: failed" >&2; tail -5 "$out/stderr" >&2; exit 1; }
    line=$(awk '{ printf "%.2f %.2f %.1f", $1, $2 + $3, $4 / 1024 }' <(tail -1 "$stats"))
    if [ -z "$best" ] || awk -v a="${line%% *}" -v b="${best%% *}" 'BEGIN { exit !(a < b) }'; then
      best=$line
    fi
  done
  rm -f "$stats"
  result[$name]=$best
  echo "$best" | awk -v n="$name" '{ printf "%-16s %7.2f s wall %7.2f s CPU %8.1f MB\n", n, $1, $2, $3 }'
}

echo "machine $machine; best of $runs; wall, CPU (user+sys), peak RSS"
for f in 1M 2M threads; do
  in=${files[$f]}
  echo "$in: $(stat -c %s "$in" | awk '{ printf "%.1f MB", $1 / 1e6 }')"
  [ "$f" = threads ] || measure "naive $f" "$build/bench/naive_goto" "$in" "$out/naive.nc"
  measure "post $f" "$build/clpost" -m $machine -o "$out/post.nc" "$in"
  measure "verify $f" "$build/clpost" -m $machine --verify -o "$out/verify.nc" "$in"
  measure "plot $f" "$build/clpost" plot -m $machine -o "$out/plot.svg" "$in"
  echo "  plot SVG: $(stat -c %s "$out/plot.svg" | awk '{ printf "%.1f MB", $1 / 1e6 }')"
done

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", (b > 0 ? a / b : 0) }'; }
field() { echo "${result[$1]}" | cut -d' ' -f"$2"; }
echo "ratios:"
for f in 1M 2M; do
  echo "  $f: post CPU / naive CPU $(ratio "$(field "post $f" 2)" "$(field "naive $f" 2)")," \
    "verify / post time $(ratio "$(field "verify $f" 1)" "$(field "post $f" 1)")," \
    "plot / post time $(ratio "$(field "plot $f" 1)" "$(field "post $f" 1)")"
done
echo "  verify RSS 2M / 1M: $(ratio "$(field "verify 2M" 3)" "$(field "verify 1M" 3)")," \
  "plot RSS 2M / 1M: $(ratio "$(field "plot 2M" 3)" "$(field "plot 1M" 3)")"
