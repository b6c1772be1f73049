#!/usr/bin/env bash
# benchmark-ao.sh [options]: install and build what is needed (scripts/setup.sh),
# then run build/bin/deepgi-benchmark-ao (time and error against the ray-traced
# reference of vtkSSAOPass and of the deep ambient obscurance, measured side by
# side in one run) under a private Xvfb when there is no DISPLAY. Options go to
# the benchmark (--help).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DEEPGI_BUILD_DIR:-$repo/build}"

bash "$repo/scripts/setup.sh"
exec bash "$repo/scripts/with-display.sh" "$build/bin/deepgi-benchmark-ao" "$@"
