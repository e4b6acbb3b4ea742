#!/usr/bin/env bash
# The Debian package: cpack builds meshlab-plugin-fcvt_<version>_amd64.deb; its control data
# depends on MeshLab 2020.09; it holds the plugin and its copyright file (DEP-5, GPL-3+:
# tests/package/check_copyright.sh); unpacked into a throw-away root (never the system), its
# plugin loads into a staged meshlabserver, which lists our filter.
# Usage: deb_installs_and_loads.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
build="$1"
source="$2"
work="$3"
rm -rf "$work"
mkdir -p "$work"

(cd "$build" && cpack -G DEB -B "$work/cpack" >"$work/cpack.log" 2>&1) || { cat "$work/cpack.log"; exit 1; }
deb=$(ls "$work"/cpack/meshlab-plugin-fcvt_*_amd64.deb)
echo "package: $(basename "$deb")"

depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
case "$depends" in
  *"meshlab (>= 2020.09~)"*"meshlab (<< 2020.10)"*) ;;
  *) echo "FAIL: the package must depend on MeshLab 2020.09" >&2; exit 1 ;;
esac

dpkg-deb -x "$deb" "$work/root"
plugin="$work/root/usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_fcvt.so"
[ -f "$plugin" ] || { echo "FAIL: $plugin missing; package contents:" >&2; dpkg-deb -c "$deb" >&2; exit 1; }
if dpkg-deb -c "$deb" | grep -v "/$" | grep -v "libfilter_fcvt.so" | grep -v "/usr/share/doc/meshlab-plugin-fcvt/copyright$" \
    | grep -q .; then
  echo "FAIL: the package holds more than the plugin and its copyright file:" >&2
  dpkg-deb -c "$deb" >&2
  exit 1
fi
bash "$source/tests/package/check_copyright.sh" "$deb"

bash "$source/scripts/stage-meshlab.sh" "$work/stage" "$plugin" >/dev/null
xvfb-run -a "$work/stage/bin/meshlabserver" -d "$work/filters.txt" >"$work/server.log" 2>&1 || true
grep -q "Remeshing: Field-Aligned CVT (FCVT)" "$work/filters.txt" || {
  echo "FAIL: the packaged plugin did not load" >&2
  tail -20 "$work/server.log" >&2
  exit 1
}
echo "ok: the packaged plugin loads in a staged meshlabserver"
