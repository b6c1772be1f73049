#!/usr/bin/env bash
# test.sh: install and build what is needed (scripts/setup.sh --paraview:
# the project and what the ParaView plugin's tests need), then run the
# whole test suite with CTest, under a private Xvfb when there is no DISPLAY
# (scripts/with-display.sh; the EGL tests remove DISPLAY themselves). Extra
# arguments go to ctest (e.g. -R Headless, -L DeepGI). The exit status is
# ctest's, and its summary is the last thing printed.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DEEPGI_BUILD_DIR:-$repo/build}"

bash "$repo/scripts/setup.sh" --paraview

# Per-test time limit in seconds: llvmpipe on 2 cores is slow, but a hung
# test must not stall the run.
timeout="${DEEPGI_TEST_TIMEOUT:-900}"
jobs="${DEEPGI_TEST_JOBS:-2}"

exec bash "$repo/scripts/with-display.sh" \
  ctest --test-dir "$build" --output-on-failure -j"$jobs" --timeout "$timeout" "$@"
