#!/usr/bin/env bash
# Runs a command on a virtual X server of its own and exits with its status.
#
#   tests/with_xvfb.sh [-a] [-s "SERVER ARGS"] COMMAND [ARGS...]
#
# The window tests use this instead of xvfb-run. xvfb-run -a picks a display
# number by looking for lock files, and the server of the test before may not
# have let go of that display yet: about one run in fifteen under load, the
# command then found no X server behind its DISPLAY. Here the server picks its
# own number (-displayfd: the first one it can really listen on) and writes it
# to us once it accepts connections; reading that is the event we wait for, not
# a guess of how long the server takes to start. Afterwards the server is
# stopped and waited for, so the next test never meets it. The -a and -s
# options are xvfb-run's, so the two are interchangeable.
set -u
server_args="-screen 0 640x480x24"
while [ $# -gt 0 ]; do
  case $1 in
    -a) shift ;;
    -s) server_args=$2; shift 2 ;;
    --) shift; break ;;
    *) break ;;
  esac
done
[ $# -gt 0 ] || { echo "usage: with_xvfb.sh [-a] [-s \"SERVER ARGS\"] COMMAND [ARGS...]" >&2; exit 2; }
command -v Xvfb >/dev/null || { echo "with_xvfb.sh: Xvfb is not installed (apt install xvfb)" >&2; exit 1; }

dir=$(mktemp -d -t with_xvfb.XXXXXX)
xvfb=""
stop_server() {
  if [ -n "$xvfb" ]; then kill "$xvfb" 2>/dev/null; wait "$xvfb" 2>/dev/null; fi
  rm -rf "$dir"
}
trap stop_server EXIT
trap 'exit 143' TERM INT

mkfifo "$dir/displayfd"
# shellcheck disable=SC2086  # the server arguments are words
Xvfb -displayfd 3 -nolisten tcp $server_args 3>"$dir/displayfd" 2>"$dir/xvfb.log" &
xvfb=$!
# The server writes its display number when it is ready, or exits (closing the
# pipe) when it cannot start. The bound only matters if it hangs.
if ! read -r -t 120 number <"$dir/displayfd" || [ -z "$number" ]; then
  echo "with_xvfb.sh: Xvfb did not start; its log:" >&2
  cat "$dir/xvfb.log" >&2
  exit 1
fi

DISPLAY=":$number" "$@"
