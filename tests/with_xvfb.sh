#!/usr/bin/env bash
# Runs a command on a virtual X server of its own and exits with its status.
#
#   tests/with_xvfb.sh [-a] [-s "SERVER ARGS"] COMMAND [ARGS...]
#
# The window tests use this instead of xvfb-run, for two reasons.
#
# -noreset: by default an X server resets itself whenever its last client
# disconnects, and a client that connects during that reset is turned away.
# A test asks `wmctrl -m` whether the window manager is up yet; when wmctrl
# came and went before openbox had connected, openbox now and then failed with
# "Failed to open the display": 3 of 286 starts in parallel loops without
# -noreset, 0 of 300 with it. xvfb-run does not pass it.
#
# -displayfd: the server picks its own display number (the first one it can
# really listen on) and writes it to us once it accepts connections; reading
# that is the event we wait for, not a guess of how long it takes to start,
# and two tests starting at once can never pick the same display (xvfb-run -a
# guesses from lock files). Afterwards the server is stopped and waited for,
# also when the test is killed. The -a and -s options are xvfb-run's, so the
# two are interchangeable.
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
command_pid=""
# shellcheck disable=SC2317  # reached through the EXIT trap below
stop_server() {
  if [ -n "$command_pid" ]; then kill "$command_pid" 2>/dev/null; wait "$command_pid" 2>/dev/null; fi
  if [ -n "$xvfb" ]; then kill "$xvfb" 2>/dev/null; wait "$xvfb" 2>/dev/null; fi
  rm -rf "$dir"
}
trap stop_server EXIT
# Killed (CTest's timeout, Ctrl-C): stop the command and the server too, so no
# X server outlives its test.
trap 'exit 143' TERM INT

mkfifo "$dir/displayfd"
# shellcheck disable=SC2086  # the server arguments are words
Xvfb -displayfd 3 -nolisten tcp -noreset $server_args 3>"$dir/displayfd" 2>"$dir/xvfb.log" &
xvfb=$!
# The server writes its display number when it is ready, or exits (closing the
# pipe) when it cannot start. The bound only matters if it hangs.
if ! read -r -t 120 number <"$dir/displayfd" || [ -z "$number" ]; then
  echo "with_xvfb.sh: Xvfb did not start; its log:" >&2
  cat "$dir/xvfb.log" >&2
  exit 1
fi

# In the background and waited for, so that a signal reaches the trap at once.
DISPLAY=":$number" "$@" &
command_pid=$!
wait "$command_pid"
status=$?
command_pid=""
exit "$status"
