#!/usr/bin/env bash
# benchmark-radiosity.sh [options]: install and build what is needed
# (scripts/setup.sh), then run build/bin/deepgi-benchmark-radiosity (time and
# error of the deep screen-space radiosity against the ray-traced one-bounce
# irradiance, measured side by side in one run) and
# build/bin/deepgi-benchmark-reflection (screen-space mirror hits against
# ray-traced hits) under a private Xvfb when there is no DISPLAY. Options go
# to the radiosity benchmark (--help); both write into its --output
# directory (default: output).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DEEPGI_BUILD_DIR:-$repo/build}"

output=output
args=("$@")
for ((i = 0; i < ${#args[@]}; ++i)); do
  if [[ "${args[$i]}" == "--output" && $((i + 1)) -lt ${#args[@]} ]]; then
    output="${args[$((i + 1))]}"
  fi
done

bash "$repo/scripts/setup.sh"
bash "$repo/scripts/with-display.sh" "$build/bin/deepgi-benchmark-radiosity" "$@"
exec bash "$repo/scripts/with-display.sh" "$build/bin/deepgi-benchmark-reflection" \
  --output "$output"
