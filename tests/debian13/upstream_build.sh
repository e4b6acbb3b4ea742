#!/usr/bin/env bash
# forky_upstream_double_build: the plugin for a double-precision MeshLab 2025.07 (its downloads,
# pymeshlab), built the way docs/meshlab.md tells users to: scripts/build-upstream-plugin.sh
# --double against the 2025.07 source tree (the forky root's /usr/src/meshlab: the upstream
# tarball), inside the forky root (GCC and Qt of a 2025.07 system). The script checks that the
# plugin links with every symbol resolved against that double-precision libmeshlab-common and
# exports Qt's plugin entry points; it also builds MeshLab's io_base plugin and the test host
# against the same library, which the forky_upstream_double_meshlab_* tests load the plugin with.
# Leaves "ok" in BUILD/forky-upstream-double/status. Usage: upstream_build.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
BUILD="$1"; SOURCE="$2"
source "$SOURCE/tests/debian13/common.sh"
require_root
upstream="$BUILD/$tag-upstream-double"
mkdir -p "$upstream"
echo "the upstream build has not finished" > "$upstream/status"
[ -f "$root/usr/src/meshlab/src/common/plugins/interfaces/filter_plugin.h" ] \
  || fail "no MeshLab source in the root's /usr/src/meshlab (${tag}_package fetches it)"
start=$(date +%s)
in_root bash "$SOURCE/scripts/build-upstream-plugin.sh" /usr/src/meshlab "$upstream" --double --with-host \
  || fail "scripts/build-upstream-plugin.sh --double failed"
echo "built in $(( $(date +%s) - start )) s"
# The same binary precision as the library: MESHLAB_SCALAR=double reached both.
grep -q "MESHLAB_SCALAR=double" "$upstream/fcvt/filter_fcvt/CMakeFiles/filter_fcvt.dir/flags.make" \
  || fail "the plugin was not compiled with MESHLAB_SCALAR=double"
grep -q "MESHLAB_SCALAR=double" "$upstream/meshlab/src/common/CMakeFiles/meshlab-common.dir/flags.make" \
  || fail "libmeshlab-common was not compiled with MESHLAB_SCALAR=double"
# That build's plugin manager checks the precision: it refuses the forky package's
# single-precision plugin (built by forky_package), as MeshLab's double downloads would.
float_dir="$upstream/float-check"
rm -rf "$float_dir"; mkdir -p "$float_dir"
cp "$upstream/plugins/libio_base.so" "$BUILD/$tag-build/filter_fcvt/libfilter_fcvt.so" "$float_dir/"
in_root "$upstream/fcvt/filter_fcvt/fcvt-meshlab-host" -P "$float_dir" -y "$float_dir/names.txt" \
  > "$float_dir/log.txt" 2>&1 || true
cat "$float_dir/log.txt"
grep -q "libfilter_fcvt.so has different floating point precision" "$float_dir/log.txt" \
  || fail "the double-precision MeshLab did not refuse the single-precision plugin"
[ ! -s "$float_dir/names.txt" ] || fail "the single-precision plugin's filters were loaded"
echo ok > "$upstream/status"
echo "PASS"
