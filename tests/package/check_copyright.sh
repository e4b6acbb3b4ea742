#!/usr/bin/env bash
# The package's copyright file (Debian policy 12.5): DEB holds
# /usr/share/doc/<package>/copyright, a regular file, not compressed, machine-readable (DEP-5:
# the Format line first, a Files paragraph) and giving the GPL version 3 (GPL-3 or GPL-3+) as the
# project's licence, with the license text or a pointer to /usr/share/common-licenses/GPL-3.
# Used by tests/package/deb_installs_and_loads.sh and tests/debian13/package.sh.
# Usage: check_copyright.sh DEB
set -euo pipefail
deb="$1"
fail() { echo "FAIL: $*" >&2; exit 1; }
package="$(dpkg-deb -f "$deb" Package)"
path="./usr/share/doc/$package/copyright"
line="$(dpkg-deb -c "$deb" | awk -v p="$path" '$NF == p')"
[ -n "$line" ] || fail "$(basename "$deb") has no $path; its files: $(dpkg-deb -c "$deb" | awk '{print $NF}' | tr '\n' ' ')"
case "$line" in
  -rw-r--r--*) ;;
  *) fail "$path should be a regular file, mode 644: $line" ;;
esac
text="$(dpkg-deb --fsys-tarfile "$deb" | tar -xO "$path")"
head -n 1 <<<"$text" | grep -qx "Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/" \
  || fail "$path does not start with the DEP-5 Format line"
files_license="$(awk '/^Files: \*$/ {f = 1; next} f && /^License:/ {print $2; exit} /^$/ {f = 0}' <<<"$text")"
case "$files_license" in
  GPL-3|GPL-3+) ;;
  *) fail "$path: the Files: * paragraph's License is '$files_license', not GPL-3 or GPL-3+" ;;
esac
grep -q "/usr/share/common-licenses/GPL-3" <<<"$text" || fail "$path does not point to /usr/share/common-licenses/GPL-3"
echo "ok: $path (DEP-5, Files: * License: $files_license)"
