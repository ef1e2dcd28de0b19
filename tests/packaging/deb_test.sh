#!/usr/bin/env bash
# The installed clpost works away from its source tree: `cmake --install --prefix P` and the .deb
# that `cpack -G DEB` makes hold the binary, the shipped machines and posts, the man page and the
# bash completion; the installed binary, run from a scratch folder, finds its machines in
# <prefix>/share/clpost (not in the source tree) and posts a sample exactly as its golden says.
# The .deb's Depends names the package of every library the binary links, and no other.
#
# Usage: deb_test.sh CPACK BUILD_DIR SOURCE_DIR   (ctest: packaging.deb; needs dpkg-dev, file)
set -euo pipefail
cpack=$1
build=$(cd "$2" && pwd)
src=$(cd "$3" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
unset CLPOST_DATA_DIR
fail() {
  echo "deb_test: FAIL: $*" >&2
  exit 1
}

# The files an install must hold, below the prefix.
expected_files() {
  {
    echo bin/clpost
    for f in "$src"/machines/*.yaml "$src"/posts/*.yaml; do
      echo "share/clpost/${f#"$src"/}"
    done
    [ -d "$src/schema" ] && (cd "$src" && find schema -type f -printf 'share/clpost/%p\n')
    echo share/man/man1/clpost.1
    echo share/bash-completion/completions/clpost
  } | sort
}

# check_prefix PREFIX: the files, and the binary posting from outside the source tree.
check_prefix() {
  local prefix=$1
  diff <(expected_files) <(cd "$prefix" && find . -type f -printf '%P\n' | sort) ||
    fail "$prefix holds other files than the install rules name"
  diff -r "$src/machines" "$prefix/share/clpost/machines" || fail "installed machines differ"
  diff -r "$src/posts" "$prefix/share/clpost/posts" || fail "installed posts differ"
  # The schema line of every shipped file leads to the installed schema, once there is one.
  if [ -d "$src/schema" ]; then
    [ -f "$prefix/share/clpost/machines/../schema/clpost-machine.schema.json" ] ||
      fail "no schema where the machines' first line says"
  fi
  cmp "$src/docs/clpost.1" "$prefix/share/man/man1/clpost.1" || fail "man page differs"
  cmp "$src/completions/clpost.bash" "$prefix/share/bash-completion/completions/clpost" ||
    fail "completion differs"
  local work=$scratch/work
  rm -rf "$work"
  mkdir -p "$work"
  cp "$src/samples/shaft-nx.cls" "$work/"
  (cd "$work" && "$prefix/bin/clpost" -m generic-lathe -o shaft-nx.nc shaft-nx.cls 2>err) ||
    fail "$prefix/bin/clpost did not post the sample: $(cat "$work/err")"
  cmp "$work/shaft-nx.nc" "$src/samples/golden/generic-lathe/shaft-nx.nc" ||
    fail "$prefix/bin/clpost: the program differs from the golden"
  # The machines come from PREFIX/share/clpost: an edited installed machine shows, and so does a
  # machine that exists only there.
  local data=$prefix/share/clpost/machines
  sed -i 's/^description: .*/description: the installed copy/' "$data/generic-lathe.yaml"
  cp "$data/fanuc-0i-t.yaml" "$data/only-installed.yaml"
  local listed
  listed=$(cd "$work" && "$prefix/bin/clpost" machines)
  grep -qx 'generic-lathe .*the installed copy' <<<"$listed" ||
    fail "$prefix/bin/clpost does not read $data/generic-lathe.yaml: $listed"
  grep -q '^only-installed ' <<<"$listed" || fail "only-installed not listed: $listed"
  (cd "$work" && "$prefix/bin/clpost" -m only-installed -o t.nc "$src/samples/thread-m20.apt" \
    2>err) || fail "-m only-installed did not post: $(cat "$work/err")"
  # The same program but for the machine's name in its header.
  sed 's/^(MACHINE ONLY-INSTALLED, /(MACHINE FANUC-0I-T, /' "$work/t.nc" |
    cmp - "$src/samples/golden/fanuc-0i-t/thread-m20.nc" ||
    fail "-m only-installed differs from fanuc-0i-t's golden"
}

# 1. cmake --install into a prefix.
cmake --install "$build" --prefix "$scratch/prefix" >/dev/null
check_prefix "$scratch/prefix"
# The build-tree binary still reads the source tree (where only-installed does not exist).
(cd "$scratch" && "$build/clpost" machines) | grep -q '^only-installed ' &&
  fail "the build-tree binary read the installed data"
(cd "$scratch" && "$build/clpost" machines) | grep -q '^generic-lathe ' ||
  fail "the build-tree binary does not find the source tree's machines"

# 2. The Debian package.
"$cpack" -G DEB --config "$build/CPackConfig.cmake" -B "$scratch/pkg" >"$scratch/cpack.log" 2>&1 ||
  { cat "$scratch/cpack.log" >&2; fail "cpack -G DEB failed"; }
debs=("$scratch"/pkg/*.deb)
[ ${#debs[@]} -eq 1 ] || fail "cpack made ${#debs[@]} packages"
deb=${debs[0]}
arch=$(dpkg --print-architecture)
version=$("$build/clpost" --version | sed 's/^clpost //')
[ "$(basename "$deb")" = "clpost_${version}_${arch}.deb" ] || fail "package name $(basename "$deb")"
field() { dpkg-deb -f "$deb" "$1"; }
[ "$(field Package)" = clpost ] || fail "Package: $(field Package)"
[ "$(field Version)" = "$version" ] || fail "Version: $(field Version)"
[ "$(field Section)" = science ] || fail "Section: $(field Section)"
[ "$(field Maintainer)" = "clpost developers <dev@clpost.invalid>" ] ||
  fail "Maintainer: $(field Maintainer)"
[ "$(field Description | head -1)" = \
  "APT/CL to NC post-processor for CNC lathes, built for threading" ] ||
  fail "Description: $(field Description | head -1)"

# Depends: exactly the packages that own the libraries the binary needs (libfmt, libyaml-cpp,
# the C++ runtime, libc; libasan and libubsan in a sanitizer build); libfmt and libyaml-cpp with
# the lowest version the binary works with (their shlibs files give one).
multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH)
needed=$(readelf -d "$build/clpost" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
owners=$(for so in $needed; do
  dpkg -S "*/$multiarch/$so" | sed -n '1s/^\([^:]*\):.*/\1/p'
done | sort -u)
depends=$(field Depends)
names=$(tr ',' '\n' <<<"$depends" | sed 's/^ *//; s/ *(.*//' | sort -u)
[ "$names" = "$owners" ] || fail "Depends: $depends; the libraries' packages: $(xargs <<<"$owners")"
grep -q 'libfmt[0-9]* (>= ' <<<"$depends" || fail "no libfmt in Depends: $depends"
grep -q 'libyaml-cpp[0-9.]* (>= ' <<<"$depends" || fail "no libyaml-cpp in Depends: $depends"

dpkg -x "$deb" "$scratch/root"
check_prefix "$scratch/root/usr"
echo "deb_test: ok: $(basename "$deb"), Depends: $depends"
