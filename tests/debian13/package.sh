#!/usr/bin/env bash
# debian13_package / forky_package: scripts/package-debian.sh builds the release's .deb in a
# fresh root of that release (BUILD/<tag>-root); then the test host fcvt-meshlab-host is built in the same root and
# installed there as /usr/local/bin/fcvt-meshlab-host. Checks the package's control data: it
# depends on exactly the release's MeshLab (2022.02 or 2025.07) and not on 2020.09, and holds only the plugin
# and its copyright file (DEP-5, GPL-3+: tests/package/check_copyright.sh). Leaves "ok" (or the
# reason it skipped) in BUILD/<tag>-out/status for the release's other tests.
# Usage: package.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
BUILD="$1"; SOURCE="$2"
source "$SOURCE/tests/debian13/common.sh"
rm -rf "$out"; mkdir -p "$out"
echo "${tag}_package has not finished" > "$out/status"

start=$(date +%s)
set +e
FCVT_BUILD_DIR="$BUILD" FCVT_DEBIAN13_FRESH="${FCVT_DEBIAN13_FRESH:-1}" \
  bash "$SOURCE/scripts/package-debian.sh" "$release" "$out"
rc=$?
set -e
if [ $rc -eq 77 ]; then
  echo "package-debian.sh skipped (not root, or debootstrap failed)" > "$out/status"
  skip "package-debian.sh could not make the $release root"
fi
[ $rc -eq 0 ] || fail "package-debian.sh $release failed ($rc)"
echo "package-debian.sh $release: $(( $(date +%s) - start )) s"

deb="$(ls "$out"/meshlab-plugin-fcvt_*+deb1[34]_amd64.deb)"
depends="$(dpkg-deb -f "$deb" Depends)"
echo "package: $(basename "$deb"); Depends: $depends"
case "$depends" in
  *"meshlab (>= $meshlab_release~)"*"meshlab (<< $meshlab_next)"*) ;;
  *) fail "the package must depend on meshlab (>= $meshlab_release~), meshlab (<< $meshlab_next)" ;;
esac
case "$depends" in *2020.*) fail "the $release package depends on MeshLab 2020.09" ;; esac
contents="$(dpkg-deb -c "$deb" | grep -v '/$' | awk '{print $NF}' | sort)"
expected="$(printf '%s\n' ./usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_fcvt.so \
  ./usr/share/doc/meshlab-plugin-fcvt/copyright | sort)"
[ "$contents" = "$expected" ] || fail "the package should hold only the plugin and its copyright file: $contents"
bash "$SOURCE/tests/package/check_copyright.sh" "$deb" || fail "the package's copyright file"

t=$(date +%s)
in_root cmake --build "$BUILD/$tag-build" -j "$(nproc)" --target fcvt_meshlab_host >"$out/host-build.log" 2>&1 \
  || { cat "$out/host-build.log"; fail "building fcvt-meshlab-host in the root"; }
install -m 755 "$BUILD/$tag-build/filter_fcvt/fcvt-meshlab-host" "$root/usr/local/bin/fcvt-meshlab-host"
echo "test host built in $(( $(date +%s) - t )) s"
echo ok > "$out/status"
echo "PASS"
