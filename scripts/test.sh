#!/usr/bin/env bash
# Builds and runs every test: the formatting check (.clang-format), the release build, then the
# same suite under AddressSanitizer and UndefinedBehaviorSanitizer, then a 30-second libFuzzer run
# of each fuzz target (scripts/fuzz.sh). The suite includes tests/packaging: `cmake --install` and
# `cpack -G DEB` (the unpacked binary posts a sample), the man page and the bash completion.
# Installs what is missing first (rs274 included, so the LinuxCNC checks run rather than skip).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh test
jobs=$(nproc)

echo "== formatting (clang-format --dry-run on every tracked source)"
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  git ls-files -z '*.cc' '*.h'
else
  find src tests bench fuzz -name '*.cc' -print0 -o -name '*.h' -print0
fi | xargs -0 clang-format --dry-run --Werror

echo "== release build and tests"
# Release, as scripts/run-sample.sh builds it: the same build/ serves both README commands, and
# CI compiles what a user gets (-O3 meets warnings -O2 does not).
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$jobs"
(cd build && ctest --output-on-failure -j "$jobs")

echo "== ASan + UBSan build and tests"
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCLPOST_SANITIZE=ON >/dev/null
cmake --build build-asan -j "$jobs"
(cd build-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --output-on-failure -j "$jobs")

echo "== fuzz smoke run (libFuzzer, 30 s per target)"
scripts/fuzz.sh 30
