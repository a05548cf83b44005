# Sourced by the window tests: find_window TITLE prints the X window id of the
# first window with that title, waiting up to 10 s for it to appear, or
# prints nothing.
find_window() {
  local window
  for _ in $(seq 100); do
    window=$(xdotool search --name "$1" 2>/dev/null | head -n 1)
    [ -n "$window" ] && { echo "$window"; return 0; }
    sleep 0.1
  done
  return 1
}
