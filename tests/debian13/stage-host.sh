#!/usr/bin/env bash
# The Debian 13 counterpart of scripts/stage-meshlab.sh for the tests in tests/meshlab/ (run with
# FCVT_MESHLAB_HOST=ROOT, see tests/meshlab/common.sh): MeshLab 2022.02 has no meshlabserver, so
#
#   STAGE/bin/meshlabserver  runs ROOT's fcvt-meshlab-host (tests/debian13/meshlab_host.cpp)
#                            inside the Debian 13 root, with meshlabserver's options
#   STAGE/lib/x86_64-linux-gnu/meshlab/plugins/lib*.so -> the root's installed MeshLab plugins,
#                            libfilter_fcvt.so among them (installed from our .deb by apt)
#
# STAGE's parent (the test's work directory) and SOURCE_DIR are bind-mounted into the root at
# their own paths, so the tests' file names mean the same inside and out.
# FCVT_HOST_BUILD=DIR (the forky_upstream_double tests): the host and the plugins are the ones
# scripts/build-upstream-plugin.sh --with-host built in DIR (bind-mounted at its own path), not
# the installed ones.
# Usage: stage-host.sh ROOT SOURCE_DIR STAGE
set -euo pipefail
root="$(cd "$1" && pwd)"; source="$(cd "$2" && pwd)"; stage="$3"
mkdir -p "$stage"
stage="$(cd "$stage" && pwd)"
work="$(dirname "$stage")"
if [ -n "${FCVT_HOST_BUILD:-}" ]; then
  host_build="$(cd "$FCVT_HOST_BUILD" && pwd)"
  host_bin="$host_build/fcvt/filter_fcvt/fcvt-meshlab-host"
  sys_plugins="$host_build/plugins"
  host_path() { echo "$1"; }                 # bind-mounted: the same path inside and out
  extra_bind=(--bind "$host_build")
else
  host_bin="/usr/local/bin/fcvt-meshlab-host"
  sys_plugins="/usr/lib/x86_64-linux-gnu/meshlab/plugins"   # inside the root
  host_path() { echo "$root$1"; }
  extra_bind=()
fi
[ -x "$(host_path "$host_bin")" ] || { echo "stage-host: no $host_bin in $root" >&2; exit 1; }
[ -f "$(host_path "$sys_plugins")/libfilter_fcvt.so" ] || { echo "stage-host: no libfilter_fcvt.so in $sys_plugins" >&2; exit 1; }
plugdir="$stage/lib/x86_64-linux-gnu/meshlab/plugins"
mkdir -p "$stage/bin" "$plugdir"
find "$plugdir" -maxdepth 1 -type l -name '*.so' -delete
for so in "$(host_path "$sys_plugins")"/*.so; do
  ln -sfn "$sys_plugins/$(basename "$so")" "$plugdir/$(basename "$so")"   # resolved inside the root
done
cat > "$stage/bin/meshlabserver" <<WRAP
#!/bin/sh
exec bash "$source/scripts/debian13-chroot.sh" "$root" --bind "$source" --bind "$work" ${extra_bind[*]} -- \\
  $host_bin -P "$plugdir" "\$@"
WRAP
chmod +x "$stage/bin/meshlabserver"
echo "$stage/bin/meshlabserver"
