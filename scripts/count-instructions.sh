#!/usr/bin/env bash
# count-instructions.sh [options]: install and build what is needed
# (scripts/setup.sh, Valgrind included), then run
# Apps/Benchmarks/deepgi_count_instructions.py (the instructions per frame
# of plain VTK and the deep G-buffer passes on Mesa llvmpipe, counted by
# Valgrind's callgrind; see Documentation/performance.md) under a private
# Xvfb when there is no DISPLAY. Options go to the script (--help);
# --output (default output) receives count-instructions.md.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DEEPGI_BUILD_DIR:-$repo/build}"

bash "$repo/scripts/setup.sh"

export PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
exec bash "$repo/scripts/with-display.sh" /usr/bin/python3 \
  "$repo/Apps/Benchmarks/deepgi_count_instructions.py" --data "$repo/Testing/Data" "$@"
