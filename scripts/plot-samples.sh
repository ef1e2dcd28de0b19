#!/usr/bin/env bash
# Regenerates the pictures in docs/img/ (shown in the README) from the samples with `clpost plot`.
# tests/plot_test.cc fails when a committed picture differs from what clpost draws now: run this,
# look at the pictures (e.g. chromium --headless --screenshot=x.png file://$PWD/docs/img/...),
# and commit them.
#
# Usage: [CLPOST_BIN=build/clpost] scripts/plot-samples.sh [OUTDIR]   (default: docs/img)
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${CLPOST_BIN:-build/clpost}
out=${1:-docs/img}
mkdir -p "$out"
# A whole part: backplot with the M20 thread's section.
"$bin" plot samples/thread-m20.apt -o "$out"/thread-m20.svg
# Flank infeed (OPTION 1), the plan.
"$bin" plot samples/threads/options.apt --thread 2 -o "$out"/option1-section.svg
# A 2-start thread, the plan.
"$bin" plot samples/threads/multistart.apt --thread 1 -o "$out"/multistart-section.svg
# A Fanuc program's G76 as the control's law expands it, measured against the plan.
"$bin" plot -m fanuc-0i-t samples/golden/fanuc-0i-t/threads-options.nc \
  --cl samples/threads/options.apt --thread 2 -o "$out"/fanuc-g76-as-cut.svg
# The Fanuc program's backplot (G92 and G76 expanded).
"$bin" plot -m fanuc-0i-t samples/golden/fanuc-0i-t/threads-options.nc \
  -o "$out"/fanuc-options-backplot.svg
# Face milling with a live tool on linuxcnc-lathe-c (XZC): the face view in the part frame.
"$bin" plot -m linuxcnc-lathe-c tests/data/millturn-face-mill.apt -o "$out"/millturn-face-mill.svg
