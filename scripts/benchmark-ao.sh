#!/usr/bin/env bash
# benchmark-ao.sh [--heldout] [options]: install and build what is needed
# (scripts/setup.sh), then run build/bin/deepgi-benchmark-ao (time and error
# against the ray-traced reference of vtkSSAOPass and of the deep ambient
# obscurance, measured side by side in one run) under a private Xvfb when
# there is no DISPLAY. Options go to the benchmark (--help).
#
# --heldout adds the held-out scenes of scripts/heldout-scenes.sh (an object
# on a floor, an interior, a volume's iso-surface, written into the build
# folder) to the
# built-in ones.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DEEPGI_BUILD_DIR:-$repo/build}"

bash "$repo/scripts/setup.sh"

args=()
for arg in "$@"; do
  if [[ "$arg" == "--heldout" ]]; then
    heldout="$build/heldout-scenes"
    bash "$repo/scripts/heldout-scenes.sh" "$heldout"
    args+=(--scenes demo,demo-columns,cornell-lucy,dragon,headsq
      --mesh "$heldout/wuson-on-floor.vtp" --mesh "$heldout/stairs-room.vtp"
      --volume "$heldout/wavelet.nhdr" --iso 160)
  else
    args+=("$arg")
  fi
done
exec bash "$repo/scripts/with-display.sh" "$build/bin/deepgi-benchmark-ao" "${args[@]}"
