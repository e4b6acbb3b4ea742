#!/usr/bin/env bash
# Builds the FCVT plugin against an upstream MeshLab source tree (2022.02 to 2025.07), for MeshLab's
# own downloads (AppImage, Windows, macOS: single or double precision) and pymeshlab (double):
#
#   bash scripts/build-upstream-plugin.sh MESHLAB_SOURCE BUILD_DIR [--double] [--with-host]
#
# MESHLAB_SOURCE: MeshLab's source tree of exactly the release the plugin is for (its top
#   directory, with ML_VERSION and src/); MeshLab's plugin manager refuses a plugin built for
#   another release ("2025.0" is compared) or another scalar precision.
# --double: MESHLAB_SCALAR=double, as MeshLab's double-precision downloads and pymeshlab; the
#   default is float, as Debian's and the single-precision downloads.
# --with-host: also MeshLab's io_base plugin and the test host fcvt-meshlab-host
#   (tests/debian13/meshlab_host.cpp), which runs the filters through this build's plugin manager.
#
# 1. MeshLab's libraries only (MESHLAB_BUILD_ONLY_LIBRARIES, MESHLAB_BUILD_MINI: no GUI, no
#    optional externals), libmeshlab-common in BUILD_DIR/meshlab/src/distrib; a Debian-style
#    source (Eigen and GLEW unbundled) takes the system's, found with pkg-config;
# 2. the plugin against those headers and that library: BUILD_DIR/fcvt/filter_fcvt/libfilter_fcvt.so
#    (linked with --no-undefined: every symbol resolves against that libmeshlab-common);
# 3. checks that the plugin exports Qt's plugin entry points (its release and precision, compiled
#    into getMLVersion(), are checked when a MeshLab loads it: the test host with --with-host).
# The plugin goes into MeshLab's plugins directory, or is loaded with Help > Plugin Info >
# Load Plugins, or pymeshlab.load_plugin(path) (docs/meshlab.md).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
usage() { echo "usage: $0 MESHLAB_SOURCE BUILD_DIR [--double] [--with-host]" >&2; exit 2; }
[ $# -ge 2 ] || usage
mlsrc="$(cd "$1" && pwd)" || usage
mkdir -p "$2"
build="$(cd "$2" && pwd)"
shift 2
scalar=float; host=0
for a in "$@"; do
  case "$a" in
    --double) scalar=double ;;
    --with-host) host=1 ;;
    *) usage ;;
  esac
done
[ -f "$mlsrc/ML_VERSION" ] && [ -f "$mlsrc/src/common/plugins/interfaces/filter_plugin.h" ] || {
  echo "build-upstream-plugin: $mlsrc is not a MeshLab 2022.02 or later source tree" \
       "(no ML_VERSION or src/common/plugins/interfaces/filter_plugin.h)" >&2; exit 1; }
version="$(tr -d '[:space:]' < "$mlsrc/ML_VERSION")"
jobs="$(nproc)"
step_start=0
step() { step_start=$(date +%s); echo "== build-upstream-plugin: $*"; }
step_done() { echo "   done in $(( $(date +%s) - step_start )) s"; }
run_logged() {  # run_logged LOG CMD...: the command's output to LOG, its tail on failure
  local log="$1"; shift
  "$@" >"$log" 2>&1 || { tail -n 40 "$log" >&2; echo "build-upstream-plugin: failed: $* (log: $log)" >&2; exit 1; }
}

ml_options=(-DCMAKE_BUILD_TYPE=Release -DMESHLAB_BUILD_ONLY_LIBRARIES=ON -DMESHLAB_BUILD_MINI=ON)
[ "$scalar" = double ] && ml_options+=(-DMESHLAB_BUILD_WITH_DOUBLE_SCALAR=ON) \
  || ml_options+=(-DMESHLAB_BUILD_WITH_DOUBLE_SCALAR=OFF)
# Upstream's tree bundles Eigen and GLEW; Debian's (dfsg) tarball does not, and MeshLab's CMake
# takes the system's only when told where Eigen is and which GLEW it is.
if [ ! -e "$mlsrc/src/vcglib/eigenlib/Eigen/Eigen" ] && [ -d /usr/include/eigen3 ]; then
  ml_options+=(-DEIGEN3_INCLUDE_DIR=/usr/include/eigen3)
fi
if [ ! -e "$mlsrc/src/external/glew-2.2.0/src/glew.c" ] && command -v pkg-config >/dev/null \
   && pkg-config --exists glew; then
  ml_options+=(-DGLEW_VERSION="$(pkg-config --modversion glew)")
fi
ml_targets=(meshlab-common)
[ "$host" = 1 ] && ml_targets+=(io_base)

step "MeshLab $version libraries ($scalar) in $build/meshlab"
run_logged "$build/meshlab-cmake.log" cmake -S "$mlsrc" -B "$build/meshlab" "${ml_options[@]}"
run_logged "$build/meshlab-build.log" cmake --build "$build/meshlab" -j "$jobs" --target "${ml_targets[@]}"
libdir="$build/meshlab/src/distrib"
[ -f "$libdir/libmeshlab-common.so" ] || { echo "build-upstream-plugin: no $libdir/libmeshlab-common.so" >&2; exit 1; }
step_done

step "the FCVT plugin against it"
fcvt_options=(-DCMAKE_BUILD_TYPE=Release -DFCVT_BUILD_CLI=OFF -DFCVT_BUILD_TESTS=OFF -DFCVT_BUILD_BENCH=OFF
  -DFCVT_MESHLAB_SOURCE_DIR="$mlsrc" -DFCVT_MESHLAB_API=2022 -DFCVT_MESHLAB_LIB_DIR="$libdir")
[ "$scalar" = double ] && fcvt_options+=(-DFCVT_MESHLAB_DOUBLE=ON) || fcvt_options+=(-DFCVT_MESHLAB_DOUBLE=OFF)
fcvt_targets=(filter_fcvt)
[ "$host" = 1 ] && fcvt_targets+=(fcvt_meshlab_host)
run_logged "$build/fcvt-cmake.log" cmake -S "$here" -B "$build/fcvt" "${fcvt_options[@]}"
run_logged "$build/fcvt-build.log" cmake --build "$build/fcvt" -j "$jobs" --target "${fcvt_targets[@]}"
plugin="$build/fcvt/filter_fcvt/libfilter_fcvt.so"
step_done

step "checks"
exports="$(nm -D --defined-only "$plugin")"
for sym in qt_plugin_instance qt_plugin_query_metadata; do
  grep -q " T $sym\$" <<<"$exports" || { echo "build-upstream-plugin: $plugin does not export $sym" >&2; exit 1; }
done
undefined="$(LD_LIBRARY_PATH="$libdir" ldd -r "$plugin" 2>&1 | grep -E 'undefined symbol|not found' || true)"
[ -z "$undefined" ] || { echo "$undefined" >&2; echo "build-upstream-plugin: unresolved symbols" >&2; exit 1; }
step_done
if [ "$host" = 1 ]; then
  mkdir -p "$build/plugins"
  cp -f "$libdir/plugins/libio_base.so" "$plugin" "$build/plugins/"
  echo "test host: $build/fcvt/filter_fcvt/fcvt-meshlab-host -P $build/plugins"
fi
echo "plugin for MeshLab $version ($scalar): $plugin"
