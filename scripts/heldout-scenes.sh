#!/usr/bin/env bash
# heldout-scenes.sh OUTDIR: writes the benchmarks' held-out scenes into
# OUTDIR (scripts/heldout-scenes.py, with VTK's Python), after installing
# Debian's assimp-testmodels, whose Wuson figure one of them uses.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [[ ! -f /usr/share/assimp/models/PLY/Wuson.ply ]]; then
  apt-get install -y --no-install-recommends assimp-testmodels >&2
fi
/usr/bin/python3 "$repo/scripts/heldout-scenes.py" "$1"
