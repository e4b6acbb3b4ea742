#!/usr/bin/env bash
# debian13_package: scripts/package-debian13.sh builds the Debian 13 .deb in a fresh Debian 13
# root (BUILD/debian13-root); then the test host fcvt-meshlab-host is built in the same root and
# installed there as /usr/local/bin/fcvt-meshlab-host. Checks the package's control data: it
# depends on MeshLab 2022.02 and not on 2020.09, and holds only the plugin. Leaves "ok" (or the
# reason it skipped) in BUILD/debian13-out/status for the other debian13 tests.
# Usage: package.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
BUILD="$1"; SOURCE="$2"
source "$SOURCE/tests/debian13/common.sh"
rm -rf "$out"; mkdir -p "$out"
echo "debian13_package has not finished" > "$out/status"

start=$(date +%s)
set +e
FCVT_BUILD_DIR="$BUILD" FCVT_DEBIAN13_FRESH="${FCVT_DEBIAN13_FRESH:-1}" \
  bash "$SOURCE/scripts/package-debian13.sh" "$out"
rc=$?
set -e
if [ $rc -eq 77 ]; then
  echo "package-debian13.sh skipped (not root, or debootstrap failed)" > "$out/status"
  skip "package-debian13.sh could not make the Debian 13 root"
fi
[ $rc -eq 0 ] || fail "package-debian13.sh failed ($rc)"
echo "package-debian13.sh: $(( $(date +%s) - start )) s"

deb="$(ls "$out"/meshlab-plugin-fcvt_*+deb13_amd64.deb)"
depends="$(dpkg-deb -f "$deb" Depends)"
echo "package: $(basename "$deb"); Depends: $depends"
case "$depends" in *"meshlab (>= 2022.02)"*) ;; *) fail "the package must depend on meshlab (>= 2022.02)" ;; esac
case "$depends" in *2020.*) fail "the Debian 13 package depends on MeshLab 2020.09" ;; esac
contents="$(dpkg-deb -c "$deb" | grep -v '/$' | awk '{print $NF}')"
[ "$contents" = "./usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_fcvt.so" ] \
  || fail "the package should hold only the plugin: $contents"

t=$(date +%s)
in_root cmake --build "$BUILD/debian13-build" -j "$(nproc)" --target fcvt_meshlab_host >"$out/host-build.log" 2>&1 \
  || { cat "$out/host-build.log"; fail "building fcvt-meshlab-host in the root"; }
install -m 755 "$BUILD/debian13-build/filter_fcvt/fcvt-meshlab-host" "$root/usr/local/bin/fcvt-meshlab-host"
echo "test host built in $(( $(date +%s) - t )) s"
echo ok > "$out/status"
echo "PASS"
