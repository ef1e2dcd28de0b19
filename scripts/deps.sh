#!/usr/bin/env bash
# Installs the Debian packages clpost needs to build and test, when they are missing.
# Usage: scripts/deps.sh [build|test|bench|package]
#   test adds rs274 from linuxcnc-uspace, clang, and what the packaging tests run (package's, and
#   groff for the man page, python3-jsonschema for the schema test, python3 for the sheet test); package: what `cpack -G DEB` needs (dpkg-shlibdeps from dpkg-dev
#   works out the Depends line, file tells CPack which files are ELF binaries).
set -euo pipefail
want=(cmake g++ ninja-build libcli11-dev libfmt-dev libyaml-cpp-dev libgtest-dev)
package=(dpkg-dev file)
if [ "${1:-build}" = test ]; then
  want+=(linuxcnc-uspace libbenchmark-dev clang libclang-rt-14-dev clang-format "${package[@]}"
    groff-base python3 python3-jsonschema python3-yaml)
fi
if [ "${1:-build}" = package ]; then
  want+=("${package[@]}")
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
