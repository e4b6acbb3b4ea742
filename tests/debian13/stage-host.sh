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
# Usage: stage-host.sh ROOT SOURCE_DIR STAGE
set -euo pipefail
root="$(cd "$1" && pwd)"; source="$(cd "$2" && pwd)"; stage="$3"
mkdir -p "$stage"
stage="$(cd "$stage" && pwd)"
work="$(dirname "$stage")"
sys_plugins="/usr/lib/x86_64-linux-gnu/meshlab/plugins"   # inside the root
[ -x "$root/usr/local/bin/fcvt-meshlab-host" ] || { echo "stage-host: no fcvt-meshlab-host in $root" >&2; exit 1; }
[ -f "$root$sys_plugins/libfilter_fcvt.so" ] || { echo "stage-host: the package is not installed in $root" >&2; exit 1; }
plugdir="$stage/lib/x86_64-linux-gnu/meshlab/plugins"
mkdir -p "$stage/bin" "$plugdir"
find "$plugdir" -maxdepth 1 -type l -name '*.so' -delete
for so in "$root$sys_plugins"/*.so; do
  ln -sfn "$sys_plugins/$(basename "$so")" "$plugdir/$(basename "$so")"   # resolved inside the root
done
cat > "$stage/bin/meshlabserver" <<WRAP
#!/bin/sh
exec bash "$source/scripts/debian13-chroot.sh" "$root" --bind "$source" --bind "$work" -- \\
  /usr/local/bin/fcvt-meshlab-host -P "$plugdir" "\$@"
WRAP
chmod +x "$stage/bin/meshlabserver"
echo "$stage/bin/meshlabserver"
