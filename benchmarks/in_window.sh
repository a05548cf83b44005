# shellcheck shell=bash
# Sourced by the windowed benchmarks. in_own_xvfb WxH SCRIPT ARGS...: unless
# it already is, the calling script runs again on a virtual X server of its
# own with a WxH screen (tests/with_xvfb.sh), with the same arguments, so
# that its windows never meet a reader's desktop or another run's.
in_own_xvfb() {
  local size=$1
  shift
  if [ -z "${VKT_IN_XVFB:-}" ]; then
    VKT_IN_XVFB=1 exec "$(dirname "${BASH_SOURCE[0]}")/../tests/with_xvfb.sh" \
      -s "-screen 0 ${size}x24" "$@"
  fi
}
