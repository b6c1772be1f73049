#!/usr/bin/env bash
# benchmark-image.sh [--heldout] [options]: install and build what is needed
# (scripts/setup.sh), then run Apps/Benchmarks/deepgi_benchmark_image.py (the
# final image of plain VTK, vtkSSAOPass and vtkDeepGIPass against the
# ray-traced reference of the pass's lighting model, side by side in one run)
# under a private Xvfb when there is no DISPLAY. Options go to the script
# (--help).
#
# --heldout adds the held-out scenes of scripts/heldout-scenes.sh (an object
# on a floor, an interior, a volume's iso-surface, written into the build
# folder).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DEEPGI_BUILD_DIR:-$repo/build}"

bash "$repo/scripts/setup.sh"

args=(--data "$repo/Testing/Data")
for arg in "$@"; do
  if [[ "$arg" == "--heldout" ]]; then
    heldout="$build/heldout-scenes"
    bash "$repo/scripts/heldout-scenes.sh" "$heldout"
    args+=(--mesh "$heldout/wuson-on-floor.vtp" --mesh "$heldout/stairs-room.vtp"
      --volume "$heldout/wavelet.nhdr" --iso 160)
  else
    args+=("$arg")
  fi
done
export PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
exec bash "$repo/scripts/with-display.sh" /usr/bin/python3 \
  "$repo/Apps/Benchmarks/deepgi_benchmark_image.py" "${args[@]}"
