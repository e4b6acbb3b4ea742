# Shared by the debian13 tests (sourced): the Debian 13 root scripts/package-debian13.sh made
# in the build directory, and running commands inside it.
# Needs BUILD and SOURCE set by the sourcing script.
fail() { echo "FAIL: $*" >&2; exit 1; }
skip() { echo "SKIP: $*"; exit 77; }
root="$BUILD/debian13-root"
out="$BUILD/debian13-out"
plugin_in_root="/usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_fcvt.so"
in_root() { bash "$SOURCE/scripts/debian13-chroot.sh" "$root" --bind "$SOURCE" --bind "$BUILD" -- "$@"; }
# The status debian13_package left: "ok", or why the root could not be made (then skip).
require_root() {
  local status
  status="$(cat "$out/status" 2>/dev/null || echo "debian13_package has not run")"
  [ "$status" = ok ] || skip "no Debian 13 root: $status"
}
require_installed() {
  require_root
  [ -f "$root$plugin_in_root" ] || fail "the package is not installed in the root (debian13_deb_installs)"
}
