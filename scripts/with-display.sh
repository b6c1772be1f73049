#!/usr/bin/env bash
# with-display.sh CMD [ARGS...]
#
# Runs CMD with an X display. When DISPLAY is already set and non-empty, CMD
# simply runs. Otherwise a private Xvfb (Mesa llvmpipe, 1920x1080x24, no TCP,
# cookie authentication) is started on a free display number (Xvfb picks it
# with -displayfd), DISPLAY and XAUTHORITY are exported for CMD, and the Xvfb
# is stopped when CMD ends. The exit status is CMD's.
#
# If Xvfb is missing or fails to start, CMD still runs, without DISPLAY, after
# a warning: the project's EGL backend needs no X server, and X11-only tests
# skip themselves.
set -uo pipefail

if [[ $# -eq 0 ]]; then
  echo "usage: $0 CMD [ARGS...]" >&2
  exit 2
fi

if [[ -n "${DISPLAY:-}" ]]; then
  "$@"
  exit $?
fi

warn() { echo "with-display.sh: $*" >&2; }

# run_without_display REASON: warn, then run the command with no DISPLAY.
run_without_display() {
  warn "$1; running without an X display (the egl backend still works)"
  unset DISPLAY
  "${command[@]}"
  exit $?
}

command=("$@")
if ! command -v Xvfb >/dev/null 2>&1; then
  run_without_display "DISPLAY is not set and Xvfb is not installed (Debian: apt-get install xvfb xauth)"
fi

workdir="$(mktemp -d "${TMPDIR:-/tmp}/with-display.XXXXXX")"
xvfb_pid=""
# shellcheck disable=SC2317  # invoked by the EXIT trap
cleanup() {
  if [[ -n "$xvfb_pid" ]] && kill -0 "$xvfb_pid" 2>/dev/null; then
    kill "$xvfb_pid" 2>/dev/null
    # Give it a moment to remove its lock file and socket.
    for _ in 1 2 3 4 5 6 7 8 9 10; do
      kill -0 "$xvfb_pid" 2>/dev/null || break
      sleep 0.1
    done
    kill -9 "$xvfb_pid" 2>/dev/null
    wait "$xvfb_pid" 2>/dev/null
  fi
  rm -rf "$workdir"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# Cookie authentication, like xvfb-run: only processes given XAUTHORITY may
# connect. The server loads every cookie in its file; the client file gets
# an entry for the display number once Xvfb has chosen it.
auth_args=()
cookie=""
if command -v xauth >/dev/null 2>&1; then
  if command -v mcookie >/dev/null 2>&1; then
    cookie="$(mcookie)"
  else
    cookie="$(od -An -N16 -tx1 /dev/urandom | tr -d ' \n')"
  fi
  if xauth -q -f "$workdir/server.auth" add :0 MIT-MAGIC-COOKIE-1 "$cookie" 2>/dev/null; then
    auth_args=(-auth "$workdir/server.auth")
  else
    cookie=""
  fi
fi

# -displayfd: Xvfb chooses a free display number and writes it to fd 3 once
# it accepts connections. -noreset: stay up between the test processes.
mkfifo "$workdir/displayfd"
Xvfb -displayfd 3 "${auth_args[@]}" -screen 0 1920x1080x24 -nolisten tcp -noreset \
  3>"$workdir/displayfd" >"$workdir/xvfb.log" 2>&1 &
xvfb_pid=$!

display_number=""
read -r -t 30 display_number <"$workdir/displayfd"
if [[ ! "$display_number" =~ ^[0-9]+$ ]] || ! kill -0 "$xvfb_pid" 2>/dev/null; then
  run_without_display "Xvfb did not start: $(tail -n 3 "$workdir/xvfb.log" 2>/dev/null | tr '\n' ' ')"
fi

export DISPLAY=":$display_number"
if [[ -n "$cookie" ]]; then
  export XAUTHORITY="$workdir/client.auth"
  xauth -q -f "$XAUTHORITY" add "$DISPLAY" MIT-MAGIC-COOKIE-1 "$cookie" 2>/dev/null
fi

"${command[@]}"
exit $?
