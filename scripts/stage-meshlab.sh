#!/usr/bin/env bash
# Builds a private MeshLab 2020.09 tree that loads our plugin without touching the system one:
#
#   STAGE/bin/meshlabserver                          copy of /usr/bin/meshlabserver
#   STAGE/bin/meshlab                                copy of /usr/bin/meshlab (the GUI), if installed
#   STAGE/lib/x86_64-linux-gnu/meshlab/libmeshlab-common.so -> system library
#   STAGE/lib/x86_64-linux-gnu/meshlab/plugins/lib*.so      -> system plugins
#   STAGE/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_fcvt.so -> PLUGIN_SO
#
# Why a copy and not a symlink: Debian's PluginManager::getBaseDirPath() starts from
# QCoreApplication::applicationDirPath(), which resolves /proc/self/exe (symlinks followed), then
# goes ../lib/x86_64-linux-gnu/meshlab (MESHLAB_LIB_INSTALL_DIR, patch 22_find-plugins) and
# loads every *.so of its plugins/ subfolder. The binary's RUNPATH
# ($ORIGIN/../lib/x86_64-linux-gnu/meshlab) finds libmeshlab-common.so in the same tree.
#
# Usage: stage-meshlab.sh STAGE_DIR PLUGIN_SO   (idempotent; re-running refreshes the links)
set -euo pipefail

if [ $# -ne 2 ]; then
  echo "usage: $0 STAGE_DIR PLUGIN_SO" >&2
  exit 2
fi
stage="$1"
plugin="$2"
sys_server="${FCVT_MESHLABSERVER:-/usr/bin/meshlabserver}"
sys_libdir="${FCVT_MESHLAB_LIBDIR:-/usr/lib/x86_64-linux-gnu/meshlab}"
libdir_rel="lib/x86_64-linux-gnu/meshlab"

[ -x "$sys_server" ] || { echo "stage-meshlab: $sys_server not found (apt-get install meshlab)" >&2; exit 1; }
[ -f "$sys_libdir/libmeshlab-common.so" ] || { echo "stage-meshlab: $sys_libdir/libmeshlab-common.so not found" >&2; exit 1; }
[ -f "$plugin" ] || { echo "stage-meshlab: plugin $plugin not found" >&2; exit 1; }

mkdir -p "$stage"
stage="$(cd "$stage" && pwd)"
plugin="$(cd "$(dirname "$plugin")" && pwd)/$(basename "$plugin")"
sys_real="$(readlink -f "$sys_libdir")"
# Refuse to write into the system tree, whatever path the caller gave.
case "$(readlink -f "$stage/$libdir_rel" 2>/dev/null || echo "$stage/$libdir_rel")" in
  "$sys_real"*) echo "stage-meshlab: $stage resolves into the system MeshLab tree" >&2; exit 1 ;;
esac

mkdir -p "$stage/bin" "$stage/$libdir_rel/plugins"
# cp to a temporary name then mv: a running meshlabserver keeps its inode, re-runs stay safe.
cp -f "$sys_server" "$stage/bin/.meshlabserver.tmp"
mv -f "$stage/bin/.meshlabserver.tmp" "$stage/bin/meshlabserver"
sys_gui="${FCVT_MESHLAB_GUI:-$(dirname "$sys_server")/meshlab}"
if [ -x "$sys_gui" ]; then
  cp -f "$sys_gui" "$stage/bin/.meshlab.tmp"
  mv -f "$stage/bin/.meshlab.tmp" "$stage/bin/meshlab"
fi
ln -sfn "$sys_libdir/libmeshlab-common.so" "$stage/$libdir_rel/libmeshlab-common.so"

plugdir="$stage/$libdir_rel/plugins"
# Drop stale links (a plugin removed from the system, an old name of ours); never real files.
find "$plugdir" -maxdepth 1 -type l -name '*.so' -delete
for so in "$sys_libdir"/plugins/*.so; do
  name="$(basename "$so")"
  [ "$name" = "$(basename "$plugin")" ] && continue  # ours wins over an installed copy
  ln -sfn "$so" "$plugdir/$name"
done
ln -sfn "$plugin" "$plugdir/$(basename "$plugin")"
echo "$stage/bin/meshlabserver"
