# Shared by the debian13 and forky tests (sourced): the root scripts/package-debian.sh made
# in the build directory, and running commands inside it.
# Needs BUILD and SOURCE set by the sourcing script.
fail() { echo "FAIL: $*" >&2; exit 1; }
skip() { echo "SKIP: $*"; exit 77; }
# FCVT_DEBIAN_RELEASE (set by tests/debian13.cmake): trixie (Debian 13, MeshLab 2022.02, the
# default) or forky (Debian testing, MeshLab 2025.07); each has its root and its results.
release="${FCVT_DEBIAN_RELEASE:-trixie}"
source "$SOURCE/scripts/debian-release.sh"
debian_release "$release" || { echo "FAIL: unknown FCVT_DEBIAN_RELEASE $release" >&2; exit 1; }
root="$BUILD/$tag-root"
out="$BUILD/$tag-out"
plugin_in_root="/usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_fcvt.so"
in_root() { bash "$SOURCE/scripts/debian13-chroot.sh" "$root" --bind "$SOURCE" --bind "$BUILD" -- "$@"; }
# The status <tag>_package left: "ok", or why the root could not be made (then skip).
require_root() {
  local status
  status="$(cat "$out/status" 2>/dev/null || echo "${tag}_package has not run")"
  [ "$status" = ok ] || skip "no $release root: $status"
}
require_installed() {
  require_root
  [ -f "$root$plugin_in_root" ] || fail "the package is not installed in the root (${tag}_deb_installs)"
}
