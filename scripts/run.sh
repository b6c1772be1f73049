#!/usr/bin/env bash
# run.sh [deepgi-render options]: install and build what is needed
# (scripts/setup.sh), then run the main job, build/bin/deepgi-render, with the
# given options. Without DISPLAY it runs under a private Xvfb
# (scripts/with-display.sh), unless the options choose the EGL backend
# (--backend egl), which needs no X server. The exit status is the job's.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DEEPGI_BUILD_DIR:-$repo/build}"

bash "$repo/scripts/setup.sh"

exe="$build/bin/deepgi-render"
if [[ ! -x "$exe" ]]; then
  echo "run.sh: $exe was not built (CMake target deepgi-render, Apps/Render)" >&2
  exit 1
fi

backend=""
previous=""
for arg in "$@"; do
  case "$arg" in
    --backend=*) backend="${arg#--backend=}" ;;
    *) [[ "$previous" == "--backend" ]] && backend="$arg" ;;
  esac
  previous="$arg"
done

if [[ "$backend" == "egl" ]]; then
  exec "$exe" "$@"
fi
exec bash "$repo/scripts/with-display.sh" "$exe" "$@"
