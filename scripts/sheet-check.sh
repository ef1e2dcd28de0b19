#!/usr/bin/env bash
# The setup sheet in a real browser: renders samples/part-turned.apt's sheet (clpost sheet) in
# headless Chromium (Debian's `chromium`, installed when missing), writes a screenshot and a PDF
# print to docs/img/ (sheet-part-turned.png, .pdf; commit them after looking at them), and checks
#  - that the page loads without a console message of level warning or error (Chromium's log on
#    stderr with --enable-logging=stderr --v=0: "CONSOLE" lines) and its DOM has every section;
#  - that the print has the expected number of pages, on Letter (Chromium's default paper) and on
#    A4 (the same page with `@page { size: A4 }`): the program and its tools, one page per
#    thread, the holes, the backplot, the warnings.
# Not run by ctest (it may install chromium); tests/sheet/sheet_test.py checks the page's content.
#
# Usage: [CLPOST_BIN=build/clpost] scripts/sheet-check.sh [OUTDIR]   (default: docs/img)
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${CLPOST_BIN:-build/clpost}
out=${1:-docs/img}
machine=fanuc-0i-t
expected_pages=5
mkdir -p "$out"

if ! command -v chromium >/dev/null; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "sheet-check: installing chromium" >&2
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends chromium >/dev/null
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
html="$work/part-turned.html"
# A fixed date (SOURCE_DATE_EPOCH) keeps the committed pictures the same from run to run.
SOURCE_DATE_EPOCH=1767225600 "$bin" sheet -m "$machine" --nc part-turned.nc -o "$html" \
  samples/part-turned.apt
# A4: the same page with the paper size set.
sed 's|@page { margin: 12mm; }|@page { size: A4; margin: 12mm; }|' "$html" >"$work/a4.html"
grep -q 'size: A4' "$work/a4.html" || { echo "sheet-check: no @page rule to set A4 in" >&2; exit 1; }

chrome=(chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --no-first-run
  --no-default-browser-check --user-data-dir="$work/profile" --enable-logging=stderr --v=0)
"${chrome[@]}" --window-size=1000,1400 --screenshot="$out/sheet-part-turned.png" \
  "file://$html" 2>"$work/shot.log" >/dev/null
"${chrome[@]}" --no-pdf-header-footer --print-to-pdf="$out/sheet-part-turned.pdf" \
  "file://$html" 2>"$work/pdf.log" >/dev/null
"${chrome[@]}" --no-pdf-header-footer --print-to-pdf="$work/a4.pdf" \
  "file://$work/a4.html" 2>"$work/a4.log" >/dev/null
"${chrome[@]}" --dump-dom "file://$html" 2>"$work/dom.log" >"$work/dom.html"

fail=0
# Console messages of the page (Chromium logs them as "CONSOLE(line)" or "CONSOLE:").
if grep -h "CONSOLE" "$work"/*.log; then
  echo "sheet-check: the page logged console messages (above)" >&2
  fail=1
fi
for id in program tools thread-1 holes backplot warnings; do
  grep -q "id=\"$id\"" "$work/dom.html" || { echo "sheet-check: no #$id in the DOM" >&2; fail=1; }
done
# Pages: the page objects of the PDF ("/Type /Page", not "/Type /Pages").
pages() { grep -a -o '/Type */Pages*' "$1" | grep -c -v 'Pages$' || true; }
for pdf in "$out/sheet-part-turned.pdf" "$work/a4.pdf"; do
  n=$(pages "$pdf")
  echo "sheet-check: $(basename "$pdf"): $n pages"
  if [ "$n" -ne "$expected_pages" ]; then
    echo "sheet-check: expected $expected_pages pages" >&2
    fail=1
  fi
done
[ -s "$out/sheet-part-turned.png" ] || { echo "sheet-check: no screenshot" >&2; fail=1; }
[ "$fail" -eq 0 ] && echo "sheet-check: ok: $out/sheet-part-turned.png, $out/sheet-part-turned.pdf"
exit "$fail"
