# shellcheck shell=bash
# Sourced by the window tests, which CTest runs under xvfb-run.
#
# The rule (book/appendix_testing.md): a window test is driven by events, never
# by the clock. The chapter runs open-ended; the script acts (resize, minimise,
# close), then waits for the event that proves the chapter reacted: a line the
# chapter writes to stderr, a window appearing, the process exiting. Every wait
# has a bound, and only a failure ever reaches it; it then says which event
# did not come. Nothing depends on how fast lavapipe draws or X answers.

# The bound on a single event, in seconds of wall-clock time. Generous: it
# only decides how long a broken run takes to fail, never whether a working
# one passes. It is a deadline, not a number of polls: on a loaded machine one
# poll can take far longer than its 0.1 s pause, and a bound counted in polls
# then outlasted CTest's own timeout, which kills the test before it can say
# which event did not come.
VKT_EVENT_SECONDS=${VKT_EVENT_SECONDS:-120}
# in_time DEADLINE: true until the wall clock reaches DEADLINE ($SECONDS).
in_time() { [ "$SECONDS" -lt "$1" ]; }

err=""   # the chapter's stderr, set by start_chapter
pid=""   # the chapter's process id

# fail MESSAGE: says what went wrong and where (the script and line that
# called fail, or the wait that called it), how long the test had run, whether
# the chapter is still running, and the last lines it printed (validation
# messages included: they may be why), then stops the chapter and the test.
fail() {
  local where="${BASH_SOURCE[1]##*/} line ${BASH_LINENO[0]}"
  [ "${FUNCNAME[1]:-}" != main ] && where="$where, in ${FUNCNAME[1]} (called from ${BASH_SOURCE[2]##*/} line ${BASH_LINENO[1]})"
  echo "FAIL: $*"
  echo "  at $where, ${SECONDS} s into the test"
  if [ -n "$err" ] && [ -f "$err" ]; then
    echo "--- the last 25 of the $(wc -l <"$err") lines the chapter printed ---"
    tail -n 25 "$err" | cut -c1-400
  fi
  if [ -n "$pid" ]; then
    if kill -0 "$pid" 2>/dev/null; then
      echo "--- the chapter (pid $pid) is still running; where its threads are ---"
      # Where it is stuck, if it is: each thread's innermost frames (gdb, where installed).
      if command -v gdb >/dev/null; then
        timeout 60 gdb -p "$pid" -batch -ex "thread apply all bt 12" 2>/dev/null | grep -E "^(Thread|#)" | cut -c1-200
      fi
    else
      echo "--- the chapter has exited ---"
    fi
  fi
  describe_x
  [ -n "$pid" ] && kill "$pid" 2>/dev/null
  exit 1
}

# describe_x: what the X server and the window manager say, for a failure:
# every window with a name, whether it is mapped, in which WM_STATE and under
# which parent (a window manager's frame, or still the root window: never
# managed), and whether the window manager still runs and answers.
describe_x() {
  echo "--- the X server's named windows (id, name, map state, WM_STATE, parent) ---"
  local w parent
  for w in $(xdotool search --name . 2>/dev/null | head -n 20); do
    parent=$(xwininfo -children -id "$w" 2>/dev/null | grep -o 'Parent window id: .*' | cut -d' ' -f4- | sed 's/ (has no name)//')
    echo "  $w '$(xdotool getwindowname "$w" 2>/dev/null)'" \
      "$(xwininfo -id "$w" 2>/dev/null | grep -o 'Map State: .*')" \
      "$(xprop -id "$w" WM_STATE 2>/dev/null | grep -o 'window state: .*' || echo 'no WM_STATE')" \
      "parent: ${parent:-?}"
  done
  if [ -n "$wm_pid" ] && ! kill -0 "$wm_pid" 2>/dev/null; then
    echo "--- the window manager (pid $wm_pid) has exited ---"
  elif wmctrl -m >/dev/null 2>&1; then
    echo "--- the window manager answers: $(wmctrl -m | head -n 1) ---"
  else
    echo "--- no window manager answers (wmctrl -m) ---"
  fi
}

# start_wm: a real window manager (openbox) on the Xvfb display, so that
# minimising and the close button work as on a desktop. Waits until openbox
# has finished starting, which is later than the moment wmctrl first gets an
# answer: openbox 3.6 takes the screen (and answers wmctrl) first, then sets
# itself up, and on the way (window_manage_all) reads every X event already
# sent to it into a queue of its own, which its main loop does not look at
# until the next event arrives. A chapter that mapped its window in between
# had its map request read there and left: the window stayed unmapped for
# as long as nothing else happened on the display, and the test failed with
# "no window titled ... appeared" (1 in a few hundred runs under load; with
# openbox held in that stretch, every run). Openbox runs its --startup
# command once that is over, just before its main loop; that command's file
# is the event we wait for.
wm_pid=""   # the window manager's process id
start_wm() {
  command -v openbox >/dev/null || fail "openbox is not installed (scripts/install-deps.sh)"
  local log; log=$(mktemp -t openbox.XXXXXX)
  local ready="$log.started"
  openbox --sm-disable --startup "touch '$ready'" >/dev/null 2>"$log" &
  wm_pid=$!
  local deadline=$((SECONDS + VKT_EVENT_SECONDS))
  while in_time "$deadline"; do
    [ -e "$ready" ] && wmctrl -m >/dev/null 2>&1 && { rm -f "$log" "$ready"; return 0; }
    kill -0 "$wm_pid" 2>/dev/null || fail "the window manager exited: $(cat "$log")"
    sleep 0.1
  done
  fail "the window manager did not start (waited ${VKT_EVENT_SECONDS} s;" \
    "$([ -e "$ready" ] && echo "it ran its start-up command" || echo "it never ran its start-up command"))"
}

# open_in_window STDERR_FILE TITLE EXE ARGS...: the window manager, then the
# chapter in the background, then its window (in $window) once viewable, its
# first frame presented and the focus given to it: where every key test
# starts.
open_in_window() {
  local log=$1 title=$2
  shift 2
  start_wm
  start_chapter "$log" "$@"
  window=$(find_window "$title") || fail "no window titled '$title' appeared"
  wait_line 0 "presented a frame at"
  activate "$window"
}

# start_chapter STDERR_FILE EXE ARGS...: runs the chapter in the background.
start_chapter() {
  err=$1; shift
  rm -f "$err"
  "$@" >/dev/null 2>"$err" &
  pid=$!
}

# find_window TITLE: prints the X window id of the chapter's window, waiting
# for it to be viewable (mapped, and by the window manager into its frame).
# Gives up at once if the chapter exits or says it runs without a window;
# when it gives up, says on stderr what became of the window.
find_window() {
  local window
  local deadline=$((SECONDS + VKT_EVENT_SECONDS))
  while in_time "$deadline"; do
    window=$(xdotool search --onlyvisible --name "$1" 2>/dev/null | head -n 1)
    [ -n "$window" ] && { echo "$window"; return 0; }
    kill -0 "$pid" 2>/dev/null || { echo "find_window: the chapter exited" >&2; return 1; }
    grep -q "running headless" "$err" 2>/dev/null &&
      { echo "find_window: the chapter opened no window (it runs headless)" >&2; return 1; }
    sleep 0.1
  done
  window=$(xdotool search --name "$1" 2>/dev/null | head -n 1)
  if [ -z "$window" ]; then
    echo "find_window: no window titled '$1' exists after ${VKT_EVENT_SECONDS} s: the chapter never created it" >&2
  elif ! xprop -id "$window" WM_STATE 2>/dev/null | grep -q 'window state'; then
    echo "find_window: window $window titled '$1' exists but the window manager never managed it" \
      "(no WM_STATE): it was never mapped, or its map request was never handled" >&2
  else
    echo "find_window: window $window titled '$1' was managed by the window manager but is not viewable" >&2
  fi
  return 1
}

# activate WINDOW: asks the window manager for the focus for the window and
# waits until the window has it. Keys are sent after this, never before: GLFW
# releases every held key when its window loses the focus, so a focus change
# that comes late (a loaded window manager) would let go of a key the test
# holds before any frame saw it held.
activate() {
  timeout "$VKT_EVENT_SECONDS" xdotool windowactivate --sync "$1" >/dev/null 2>&1 ||
    fail "the window manager did not give the window the focus (waited ${VKT_EVENT_SECONDS} s)"
}

# mark: the number of lines the chapter has written so far; wait_line MARK
# REGEX waits for a line matching REGEX written after that mark.
mark() { wc -l <"$err"; }
wait_line() {
  local from=$(($1 + 1)) what=$2
  local deadline=$((SECONDS + VKT_EVENT_SECONDS))
  while in_time "$deadline"; do
    tail -n "+$from" "$err" | grep -qE "$what" && return 0
    kill -0 "$pid" 2>/dev/null || { tail -n "+$from" "$err" | grep -qE "$what" && return 0; fail "the chapter exited before it said: $what"; }
    sleep 0.1
  done
  fail "the chapter never said: $what (waited ${VKT_EVENT_SECONDS} s)"
}

# resize WINDOW W H: resizes the window and waits until the chapter has
# recreated its swapchain at that size and presented a frame of it.
resize() {
  local m; m=$(mark)
  xdotool windowsize "$1" "$2" "$3" || fail "xdotool could not resize the window"
  wait_line "$m" "swapchain recreated at $2x$3"
  wait_line "$m" "presented a frame at $2x$3"
}

# wait_exit: waits for the chapter to exit and sets $status.
wait_exit() {
  local deadline=$((SECONDS + VKT_EVENT_SECONDS))
  while in_time "$deadline"; do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  kill -0 "$pid" 2>/dev/null && fail "the chapter did not exit after its window was closed"
  wait "$pid"
  status=$?
  pid=""
}

# close_with_wm WINDOW: the window manager's close (the title bar's X button):
# _NET_CLOSE_WINDOW, which openbox turns into WM_DELETE_WINDOW for GLFW.
close_with_wm() { wmctrl -i -c "$1" || fail "wmctrl could not close the window"; wait_exit; }
# close_with_escape WINDOW: the key every chapter quits on. Pressed, then
# released only once the chapter has exited: the press alone closes the
# window, and a release sent after it found the window gone (BadWindow), so
# "xdotool key Escape" failed now and then although the chapter had quit
# cleanly (18's window_keys, 1 run in 60 of it and 19's under load). Once
# the window has the focus, xdotool sends through XTEST, so the release must
# still come, or the X server would go on holding Escape.
close_with_escape() {
  xdotool keydown --window "$1" Escape || fail "xdotool could not press Escape"
  wait_exit
  xdotool keyup Escape 2>/dev/null
}

# expect_clean_status: the chapter exited 0 with a clean validation report.
expect_clean_status() {
  [ "$status" -eq 0 ] || fail "exit status $status"
  grep -q "validation: 0 warnings, 0 errors" "$err" || fail "validation was not clean"
}

# quit_with_escape WINDOW: Escape, then the chapter's lines for the log (its
# validation messages left out) and expect_clean_status.
quit_with_escape() {
  close_with_escape "$1"
  grep -v '^\[validation' "$err"
  expect_clean_status
}

# expect_clean_exit SCREENSHOT W H: expect_clean_status, and a screenshot of
# the last frame presented, at W x H.
expect_clean_exit() {
  expect_clean_status
  grep -q "wrote .* ($2x$3)" "$err" || fail "the screenshot is not of the last size, $2x$3"
  [ -f "$1" ] || fail "no screenshot was written"
}

# check_last_frame PICTURE CHECKER PNG W H: the last frame is the chapter's
# picture. PICTURE "triangle": chapter 04's (check_triangle); "any": only its
# size is checked (expect_clean_exit), for chapter 03, whose colour follows the
# wall clock in an open-ended window run.
check_last_frame() {
  case $1 in
    triangle) check_triangle "$2" "$3" "$4" "$5" ;;
    any) return 0 ;;
    *) fail "unknown picture '$1'" ;;
  esac
}

# check_triangle CHECKER PNG W H: chapter 04's picture at any size has the
# clear colour in its corners and, at its centre (clip space 0,0, where the
# vertex colours mix 1/2 red, 1/4 green, 1/4 blue), linear (0.55, 0.35, 0.325),
# which the _SRGB target stores as (196, 160, 154); the tolerance covers the
# half-pixel offset of the centre sample (and, in tiny pictures, the edges).
check_triangle() {
  "$1" --png "$2" --pixel 0,0,39,39,56 --pixel $(($3 - 1)),$(($4 - 1)),39,39,56 \
       --pixel $(($3 / 2)),$(($4 / 2)),196,160,154,3
}

# main_thread_ticks: CPU time (user + system, in clock ticks) of the chapter's
# main thread, from /proc.
main_thread_ticks() { awk '{print $14 + $15}' "/proc/$pid/task/$pid/stat"; }
