#!/usr/bin/env bash
# RunClientServer.sh MPIEXEC RANKS TIMEOUT CLIENT_SCRIPT ARGS...
#
# ParaView's client-server mode on one machine: pvserver on RANKS MPI ranks
# listens on a free port, and the client, /usr/bin/python3 CLIENT_SCRIPT
# ARGS... localhost:PORT (ParaView's modules come from PYTHONPATH),
# connects to it. Both must end within TIMEOUT seconds; the exit status is
# the client's, or 1 with a message when either did not end in time.
set -uo pipefail
mpiexec="$1" ranks="$2" limit="$3"
shift 3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
port="$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
log="$(mktemp)"
setsid "$mpiexec" --oversubscribe -n "$ranks" pvserver --server-port="$port" >"$log" 2>&1 &
server=$!
trap 'kill -- -"$server" 2>/dev/null; rm -f "$log"' EXIT
for _ in $(seq 60); do
  grep -q "Accepting connection" "$log" && break
  sleep 1
done
if ! grep -q "Accepting connection" "$log"; then
  echo "RunClientServer.sh: pvserver on $ranks ranks did not start listening within 60 s:" >&2
  cat "$log" >&2
  exit 1
fi
timeout "$limit" /usr/bin/python3 "$@" "localhost:$port"
status=$?
if ((status == 124)); then
  echo "RunClientServer.sh: the client did not finish within $limit s (a rank waiting for the others?)" >&2
  exit 1
fi
for _ in $(seq 30); do
  kill -0 "$server" 2>/dev/null || break
  sleep 1
done
if kill -0 "$server" 2>/dev/null; then
  echo "RunClientServer.sh: pvserver did not end within 30 s of its client" >&2
  exit 1
fi
exit "$status"
