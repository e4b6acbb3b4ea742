#!/usr/bin/env bash
# debian13_deb_installs: the Debian 13 package installs with apt-get inside the Debian 13 root
# (its dependencies, MeshLab 2022.02 among them, resolved by apt), the plugin lands in MeshLab's
# plugin directory, and apt-get removes it again cleanly before the final install the other
# debian13 tests use. Usage: deb_installs.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
BUILD="$1"; SOURCE="$2"
source "$SOURCE/tests/debian13/common.sh"
require_root
deb="$(ls "$out"/meshlab-plugin-fcvt_*+deb1[34]_amd64.deb)"
in_root sh -c 'dpkg -s meshlab-plugin-fcvt >/dev/null 2>&1 && apt-get purge -y -qq meshlab-plugin-fcvt || true' >/dev/null
in_root apt-get install -y -qq --no-install-recommends "$deb" > "$out/apt-install.log" 2>&1 \
  || { cat "$out/apt-install.log"; fail "apt-get install $deb in the root"; }
in_root dpkg-query -W -f='${Status} ${Version}\n' meshlab-plugin-fcvt | tee "$out/dpkg-status.txt"
grep -q "install ok installed" "$out/dpkg-status.txt" || fail "not installed"
[ -f "$root$plugin_in_root" ] || fail "$plugin_in_root missing after the install"
in_root dpkg -L meshlab-plugin-fcvt | grep -qx "$plugin_in_root" || fail "dpkg does not list $plugin_in_root"
echo "MeshLab $(in_root dpkg-query -W -f='${Version}' meshlab) with meshlab-plugin-fcvt $(in_root dpkg-query -W -f='${Version}' meshlab-plugin-fcvt)"
# Removal and reinstall: what a user's upgrade does.
in_root apt-get remove -y -qq meshlab-plugin-fcvt >/dev/null 2>&1 || fail "apt-get remove"
[ ! -e "$root$plugin_in_root" ] || fail "the plugin stays after apt-get remove"
in_root apt-get install -y -qq --no-install-recommends "$deb" >> "$out/apt-install.log" 2>&1 || fail "reinstall"
echo "PASS"
