#!/usr/bin/env bash
# Rewrites the golden NC files beside every sample (samples/<stem>.<machine><ext>) from the
# current build. Review `git diff samples/` line by line before committing: the goldens are the
# project's statement of what each machine receives.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${CLPOST_BIN:-build/clpost}
for cl in samples/*.cls samples/*.ncl samples/*.apt samples/*.cl; do
  [ -e "$cl" ] || continue
  stem=${cl%.*}
  "$bin" -m generic-lathe -o "$stem.generic-lathe.nc" "$cl"
  "$bin" -m linuxcnc-lathe -o "$stem.linuxcnc-lathe.ngc" "$cl"
done
git status --short samples/
