#!/usr/bin/env bash
# Rewrites the golden NC files (samples/golden/<machine>/<name><ext>) from the current build:
# every sample in samples/ and samples/threads/ on every shipped machine, and
# samples/machines/<machine>.* on its own machine, samples/millturn/*.apt (as millturn-<stem>) on
# every machine with live tools; a sample a machine refuses as its errors, <name>.err. Review
# `git diff samples/golden` line by line
# before committing: the goldens are the project's statement of what each machine receives.
# The list of pairs is golden_cases() in tests/golden_test.cc; keep the two in step.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${CLPOST_BIN:-build/clpost}
"$bin" machines | while read -r machine ext _; do
  mkdir -p "samples/golden/$machine"
  millturn=()  # (not grep -q: closing the pipe early would fail under pipefail)
  if "$bin" machines show "$machine" | grep -x 'millturn.live_tools: true' >/dev/null; then
    millturn=(samples/millturn/*.apt)
  fi
  for cl in samples/*.cls samples/*.ncl samples/*.apt samples/*.cl samples/threads/*.apt \
            samples/machines/"$machine".* "${millturn[@]}"; do
    [ -e "$cl" ] || continue
    case "$cl" in *.nc|*.ngc|*.mpf|*.h|*.txt) continue ;; esac
    name=$(basename "${cl%.*}")
    case "$cl" in
      samples/threads/*) name="threads-$name" ;;
      samples/millturn/*) name="millturn-$name" ;;
    esac
    # A refused sample's golden is its errors (<name>.err): the reviewed refusal.
    if "$bin" -m "$machine" -o "samples/golden/$machine/$name$ext" "$cl" \
        2>"samples/golden/$machine/$name.err"; then
      rm -f "samples/golden/$machine/$name.err"
    else
      rm -f "samples/golden/$machine/$name$ext"
      echo "update-goldens: $cl on $machine refused (samples/golden/$machine/$name.err)" >&2
    fi
  done
done
git status --short samples/
