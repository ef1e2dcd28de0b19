#!/usr/bin/env bash
# Installs the Debian packages clpost needs to build and test, when they are missing.
# Usage: scripts/deps.sh [build|test|bench]   (test adds rs274 from linuxcnc-uspace, and clang)
set -euo pipefail
want=(cmake g++ ninja-build libcli11-dev libfmt-dev libyaml-cpp-dev libgtest-dev)
if [ "${1:-build}" = test ]; then
  want+=(linuxcnc-uspace libbenchmark-dev clang libclang-rt-14-dev clang-format)
fi
if [ "${1:-build}" = bench ]; then  # bench/run.sh: Google Benchmark and GNU time
  want+=(libbenchmark-dev time)
fi
missing=()
for p in "${want[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "clpost: installing ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
