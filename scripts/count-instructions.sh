#!/usr/bin/env bash
# count-instructions.sh [options]: install and build what is needed
# (scripts/setup.sh, Valgrind included), then run
# Apps/Benchmarks/deepgi_count_instructions.py under callgrind (the
# instructions per frame of plain VTK and the deep G-buffer passes on Mesa
# llvmpipe, rasterising in the calling thread; see
# Documentation/performance.md) under a private Xvfb when there is no
# DISPLAY. Options go to the script (--help); --output (default output)
# receives count-instructions.md.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DEEPGI_BUILD_DIR:-$repo/build}"

bash "$repo/scripts/setup.sh"

dumps="$(mktemp -d)"
trap 'rm -rf "$dumps"' EXIT
export PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
# One thread: llvmpipe's rasterisation runs where callgrind counts it, and
# the count does not depend on how the threads interleave.
export LP_NUM_THREADS=0
bash "$repo/scripts/with-display.sh" valgrind --tool=callgrind --instr-atstart=no \
  --callgrind-out-file="$dumps/callgrind.out" /usr/bin/python3 \
  "$repo/Apps/Benchmarks/deepgi_count_instructions.py" --data "$repo/Testing/Data" \
  --callgrind-output "$dumps/callgrind.out" "$@" 2> "$dumps/valgrind.log" ||
  { cat "$dumps/valgrind.log" >&2; exit 1; }
