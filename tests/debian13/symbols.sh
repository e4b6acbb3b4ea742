#!/usr/bin/env bash
# debian13_plugin_symbols: the installed plugin resolves every symbol against Debian 13's
# libraries: `ldd -r` (all data and function relocations processed) inside the root, with
# MeshLab's private library directory on the search path as MeshLab's own RUNPATH puts it, reports
# no missing library and no undefined symbol; and its needed libraries include libmeshlab-common
# from /usr/lib/x86_64-linux-gnu/meshlab. Usage: symbols.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
BUILD="$1"; SOURCE="$2"
source "$SOURCE/tests/debian13/common.sh"
require_installed
in_root env LD_LIBRARY_PATH=/usr/lib/x86_64-linux-gnu/meshlab ldd -r "$plugin_in_root" > "$out/ldd.txt" 2>&1 || true
cat "$out/ldd.txt"
! grep -q "not found" "$out/ldd.txt" || fail "a library the plugin needs is missing"
! grep -q "undefined symbol" "$out/ldd.txt" || fail "undefined symbols"
grep -q "libmeshlab-common.so => /usr/lib/x86_64-linux-gnu/meshlab/libmeshlab-common.so" "$out/ldd.txt" \
  || fail "not linked to Debian 13's libmeshlab-common"
echo "PASS"
