#!/usr/bin/env bash
# Quick start: install what is missing, build, and post a sample on the default machine.
# Usage: scripts/run-sample.sh [sample.cl] [clpost options...]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh build
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target clpost >/dev/null
sample=${1:-samples/shaft-nx.cls}
shift || true
exec build/clpost "$@" "$sample"
