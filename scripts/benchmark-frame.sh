#!/usr/bin/env bash
# benchmark-frame.sh [options]: install and build what is needed
# (scripts/setup.sh), then run Apps/Benchmarks/deepgi_benchmark_frame.py (the
# frame time of plain VTK, vtkSSAOPass and every deep G-buffer pass side by
# side in one run, each deep pass's time split into its stages; see
# Documentation/performance.md) under a private Xvfb when there is no
# DISPLAY. Options go to the script (--help).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DEEPGI_BUILD_DIR:-$repo/build}"

bash "$repo/scripts/setup.sh"

export PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
exec bash "$repo/scripts/with-display.sh" /usr/bin/python3 \
  "$repo/Apps/Benchmarks/deepgi_benchmark_frame.py" --data "$repo/Testing/Data" "$@"
