# Sourced by the window tests.

# find_window TITLE prints the X window id of the first window with that
# title, waiting up to 30 s for it to appear (a loaded CI machine starts the
# X server and the chapter slowly), or prints nothing.
find_window() {
  local window
  for _ in $(seq 300); do
    window=$(xdotool search --name "$1" 2>/dev/null | head -n 1)
    [ -n "$window" ] && { echo "$window"; return 0; }
    sleep 0.1
  done
  return 1
}

# check_triangle CHECKER PNG W H: chapter 04's picture at any size has the
# clear colour in its corners and, at its centre (clip space 0,0, where the
# vertex colours mix 1/2 red, 1/4 green, 1/4 blue), linear (0.55, 0.35, 0.325),
# which the _SRGB target stores as (196, 160, 154); the tolerance covers the
# half-pixel offset of the centre sample.
check_triangle() {
  "$1" --png "$2" --pixel 0,0,39,39,56 --pixel $(($3 - 1)),$(($4 - 1)),39,39,56 \
       --pixel $(($3 / 2)),$(($4 / 2)),196,160,154,3
}
