#!/usr/bin/env bash
# pymeshlab_plugin_build (label pymeshlab): the plugin for pymeshlab, built on this machine as
# docs/meshlab.md tells users to: scripts/build-upstream-plugin.sh MESHLAB_SOURCE BUILD --double
# against MeshLab 2025.07's source tree, the one the forky tests build against (the forky root's
# /usr/src/meshlab: Debian's upstream tarball of 2025.07, unpacked by scripts/package-debian.sh).
# That tree is taken, in this order, from
#   FCVT_MESHLAB2025_SOURCE   a MeshLab 2025.07 source tree given in the environment;
#   WORK/meshlab-src          the copy an earlier run made (kept between runs);
#   the root cache            scripts/root-cache.sh's forky entry (FCVT_ROOT_CACHE, default
#                             /var/cache/fcvt-roots), only its usr/src/meshlab unpacked (seconds);
#   BUILD/forky-root          the forky root forky_package made in this build directory.
# The build (MeshLab's double-precision libmeshlab-common, about 10 minutes on two cores the first
# time, then the plugin) stays in WORK/upstream and is incremental on later runs.
# Leaves "ok" in WORK/status, or the reason the pymeshlab tests are skipped.
# Usage: build_plugin.sh SOURCE_DIR BUILD_DIR WORK_DIR
set -euo pipefail
source="$(cd "$1" && pwd)"; build="$2"; work="$3"
mkdir -p "$work"
work="$(cd "$work" && pwd)"
status="$work/status"
skip() { echo "skipped: $*"; echo "skipped: $*" > "$status"; exit 77; }
fail() { echo "FAIL: $*" >&2; echo "failed: $*" > "$status"; exit 1; }
echo "the plugin build has not finished" > "$status"

pymeshlab_dir="${FCVT_PYMESHLAB_DIR:-$source/../shared/pymeshlab}"
[ -f "$pymeshlab_dir/pymeshlab/__init__.py" ] \
  || skip "no pymeshlab in $pymeshlab_dir (../shared/pymeshlab; FCVT_PYMESHLAB_DIR sets another)"
[ -x /usr/bin/python3 ] || skip "no /usr/bin/python3"

is_2025_07() { [ -f "$1/src/common/plugins/interfaces/filter_plugin.h" ] && [ "$(tr -d '[:space:]' < "$1/ML_VERSION" 2>/dev/null)" = 2025.07 ]; }
mlsrc=""
if [ -n "${FCVT_MESHLAB2025_SOURCE:-}" ]; then
  is_2025_07 "$FCVT_MESHLAB2025_SOURCE" || fail "FCVT_MESHLAB2025_SOURCE=$FCVT_MESHLAB2025_SOURCE is not a MeshLab 2025.07 source tree"
  mlsrc="$(cd "$FCVT_MESHLAB2025_SOURCE" && pwd)"
elif is_2025_07 "$work/meshlab-src"; then
  mlsrc="$work/meshlab-src"
else
  rm -rf "$work/meshlab-src" "$work/meshlab-src.partial"
  mkdir -p "$work/meshlab-src.partial"
  cache_dir="${FCVT_ROOT_CACHE:-/var/cache/fcvt-roots}"
  entry=""
  [ "$cache_dir" = off ] || entry="$(ls -t "$cache_dir"/forky-*.tar.zst "$cache_dir"/forky-*.tar 2>/dev/null | head -n 1 || true)"
  if [ -n "$entry" ]; then
    echo "MeshLab 2025.07 source: ./usr/src/meshlab of $entry"
    case "$entry" in
      *.zst) zstd -dc "$entry" | tar -x -C "$work/meshlab-src.partial" ./usr/src/meshlab ;;
      *) tar -x -f "$entry" -C "$work/meshlab-src.partial" ./usr/src/meshlab ;;
    esac || fail "could not unpack usr/src/meshlab from $entry"
  elif is_2025_07 "$build/forky-root/usr/src/meshlab"; then
    echo "MeshLab 2025.07 source: $build/forky-root/usr/src/meshlab"
    mkdir -p "$work/meshlab-src.partial/usr/src"
    cp -a "$build/forky-root/usr/src/meshlab" "$work/meshlab-src.partial/usr/src/"
  else
    rm -rf "$work/meshlab-src.partial"
    skip "no MeshLab 2025.07 source tree: none in the root cache ($cache_dir/forky-*), no $build/forky-root" \
         "(ctest -L forky makes both; or set FCVT_MESHLAB2025_SOURCE)"
  fi
  mv "$work/meshlab-src.partial/usr/src/meshlab" "$work/meshlab-src"
  rm -rf "$work/meshlab-src.partial"
  is_2025_07 "$work/meshlab-src" || fail "the unpacked tree $work/meshlab-src is not MeshLab 2025.07"
  mlsrc="$work/meshlab-src"
fi
echo "MeshLab source: $mlsrc (ML_VERSION $(cat "$mlsrc/ML_VERSION"))"

start=$(date +%s)
bash "$source/scripts/build-upstream-plugin.sh" "$mlsrc" "$work/upstream" --double \
  || fail "scripts/build-upstream-plugin.sh --double failed"
plugin="$work/upstream/fcvt/filter_fcvt/libfilter_fcvt.so"
[ -f "$plugin" ] || fail "no $plugin"
grep -q "MESHLAB_SCALAR=double" "$work/upstream/fcvt/filter_fcvt/CMakeFiles/filter_fcvt.dir/flags.make" \
  || fail "the plugin was not compiled with MESHLAB_SCALAR=double"
echo "built in $(( $(date +%s) - start )) s: $plugin"
echo ok > "$status"
echo "PASS"
