#!/usr/bin/env bash
# The speed and memory figures of clpost (README "Performance"): builds Release, generates the
# benchmark data (bench/gen_cl), posts the large file on generic-lathe and prints MB/s, lines/s
# and peak RSS next to `wc -l` on the same file, and the same program as binary CLDATA (gen_cl
# binary); then a batch of small files with -j1 and -j2.
# Each timing is the best of RUNS runs (default 5).
#
#   bench/run.sh                 GOTOS=1000000 BATCH_FILES=200 RUNS=5 BUILD=build-release
#   bench/run.sh --suite         also runs the Google Benchmark suite (clpost_bench)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD:-$root/build-release}
data=${DATA:-${TMPDIR:-/tmp}/clpost-bench}
gotos=${GOTOS:-1000000}
batch_files=${BATCH_FILES:-200}
runs=${RUNS:-5}

"$root/scripts/deps.sh" bench
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCLPOST_TESTS=OFF >/dev/null
targets=(clpost gen_cl)
[ "${1:-}" = --suite ] && targets+=(clpost_bench)
cmake --build "$build" --target "${targets[@]}" >/dev/null

mkdir -p "$data"
large=$data/large-$gotos.cl
[ -s "$large" ] || "$build/bench/gen_cl" large "$large" "$gotos"
large_bin=$data/large-$gotos.cldata
[ -s "$large_bin" ] || "$build/bench/gen_cl" binary "$large" "$large_bin"
small=$data/small-$batch_files
if [ ! -d "$small" ]; then
  mkdir -p "$small.tmp" && "$build/bench/gen_cl" small "$small.tmp" "$batch_files" && mv "$small.tmp" "$small"
fi
out=$data/out
rm -rf "$out" && mkdir -p "$out"

# best_of CMD...: runs CMD $runs times; prints "wall user sys maxrss_kb" of the fastest run (wall
# clock from bash's EPOCHREALTIME, CPU times and peak RSS from GNU time).
best_of() {
  local best="" line t0 t1 stats
  stats=$(mktemp)
  for _ in $(seq "$runs"); do
    t0=$EPOCHREALTIME
    /usr/bin/time -o "$stats" -f "%U %S %M" "$@" >/dev/null
    t1=$EPOCHREALTIME
    line="$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.4f", b - a }') $(tail -1 "$stats")"
    if [ -z "$best" ] || awk -v a="${line%% *}" -v b="${best%% *}" 'BEGIN { exit !(a < b) }'; then
      best=$line
    fi
  done
  rm -f "$stats"
  echo "$best"
}

bytes=$(stat -c %s "$large")
lines=$(wc -l <"$large")
read -r wc_wall _ _ wc_rss < <(best_of wc -l "$large")
read -r wall user sys rss < <(best_of "$build/clpost" -m generic-lathe -o "$out/large.nc" "$large")
out_bytes=$(stat -c %s "$out/large.nc")

awk -v file="$large" -v bytes="$bytes" -v lines="$lines" -v wall="$wall" -v user="$user" -v sys="$sys" \
    -v rss="$rss" -v wc_wall="$wc_wall" -v wc_rss="$wc_rss" -v out_bytes="$out_bytes" 'BEGIN {
  mb = bytes / 1e6
  printf "%s: %.1f MB, %d lines\n", file, mb, lines
  printf "%-28s %8.3f s %9.1f MB/s %12.0f lines/s %7.1f MB peak RSS\n", "wc -l", wc_wall,
         mb / wc_wall, lines / wc_wall, wc_rss / 1024
  printf "%-28s %8.3f s %9.1f MB/s %12.0f lines/s %7.1f MB peak RSS\n", "clpost (generic-lathe)",
         wall, mb / wall, lines / wall, rss / 1024
  cpu = user + sys
  printf "%-28s %8.3f s %9.1f MB/s   (%.1f MB of NC written)\n", "clpost, CPU time (user+sys)",
         cpu, mb / cpu, out_bytes / 1e6
}'

# The same program as binary CLDATA (APT360 records): MB/s of the binary file, and points per second
# to compare with the text's lines per second.
bin_bytes=$(stat -c %s "$large_bin")
read -r bwall buser bsys brss < <(best_of "$build/clpost" -m generic-lathe -o "$out/large-bin.nc" "$large_bin")
awk -v bytes="$bin_bytes" -v gotos="$gotos" -v wall="$bwall" -v user="$buser" -v sys="$bsys" \
    -v rss="$brss" 'BEGIN {
  mb = bytes / 1e6
  printf "%-28s %8.3f s %9.1f MB/s %12.0f GOTOs/s %7.1f MB peak RSS (%.1f MB binary CLDATA)\n",
         "clpost, binary CLDATA", wall, mb / wall, gotos / wall, rss / 1024, mb
  printf "%-28s %8.3f s %9.1f MB/s\n", "clpost, binary, CPU time", user + sys, mb / (user + sys)
}'

nfiles=$(find "$small" -name '*.cl' | wc -l)
small_bytes=$(du -sb "$small" | cut -f1)
rm -rf "$out/j1" "$out/j2"
read -r j1_wall _ _ _ < <(best_of "$build/clpost" -q -j 1 -r -d "$out/j1" "$small")
read -r j2_wall _ _ _ < <(best_of "$build/clpost" -q -j 2 -r -d "$out/j2" "$small")
cmp -s <(cd "$out/j1" && cat ./*) <(cd "$out/j2" && cat ./*) || { echo "batch: -j1 and -j2 differ" >&2; exit 1; }
awk -v n="$nfiles" -v b="$small_bytes" -v j1="$j1_wall" -v j2="$j2_wall" 'BEGIN {
  printf "batch of %d files (%.1f MB): -j1 %.3f s, -j2 %.3f s: speedup %.2fx\n", n, b / 1e6, j1,
         j2, j1 / j2
}'

if [ "${1:-}" = --suite ]; then
  "$build/bench/clpost_bench"
fi
