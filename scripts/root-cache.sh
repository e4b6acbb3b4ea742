# Sourced by scripts/package-debian.sh: a cache of the Debian roots it makes, outside the clone, so
# that a second CI run on the same machine unpacks a root (seconds) instead of making it with
# debootstrap and apt (minutes).
#
#   FCVT_ROOT_CACHE   the cache directory (default /var/cache/fcvt-roots); "off" disables it
#   FCVT_ROOT_CACHE_DAYS  entries older than this are made again (default 30: a testing or
#                     unstable archive moves on, and the root should follow it now and then)
#
# An entry is one archive, <tag>-<key>.tar.zst (.tar without zstd), of a ready root: debootstrap,
# the packages installed, the apt caches emptied, MeshLab's source unpacked in /usr/src/meshlab.
# The key is a hash of what made it: the release, the archive address, the package list and
# the version of this file's format. An entry is only ever written whole (written aside, then
# renamed) and only read; the root in the build directory is always a fresh copy of it.

root_cache_format=1

# root_cache_entry TAG RELEASE ARCHIVE PACKAGES... -> prints the entry's path (no file check)
root_cache_entry() {
  local tag="$1" release="$2" archive="$3"; shift 3
  local dir="${FCVT_ROOT_CACHE:-/var/cache/fcvt-roots}"
  local key ext=tar
  key="$(printf '%s\n' "format $root_cache_format" "$release" "$archive" "$@" | sha256sum | cut -c1-16)"
  command -v zstd >/dev/null && ext=tar.zst
  echo "$dir/$tag-$key.$ext"
}

root_cache_enabled() { [ "${FCVT_ROOT_CACHE:-}" != off ]; }

# root_cache_fresh ENTRY: the entry exists and is younger than FCVT_ROOT_CACHE_DAYS
root_cache_fresh() {
  [ -f "$1" ] && [ -n "$(find "$1" -mmin -$(( ${FCVT_ROOT_CACHE_DAYS:-30} * 1440 )) 2>/dev/null)" ]
}

# root_cache_restore ENTRY ROOT: ROOT becomes a copy of the entry
root_cache_restore() {
  local entry="$1" root="$2"
  rm -rf "$root"
  mkdir -p "$root"
  case "$entry" in
    *.zst) tar --zstd --numeric-owner -xpf "$entry" -C "$root" ;;
    *) tar --numeric-owner -xpf "$entry" -C "$root" ;;
  esac
}

# root_cache_save ROOT ENTRY: stores ROOT (not mounted into, nothing running in it) as the entry
root_cache_save() {
  local root="$1" entry="$2" tmp
  mkdir -p "$(dirname "$entry")"
  tmp="$entry.$$.partial"
  case "$entry" in
    *.zst) tar --numeric-owner -cpf - -C "$root" . | zstd -q -T0 -3 -o "$tmp" ;;
    *) tar --numeric-owner -cpf "$tmp" -C "$root" . ;;
  esac
  mv -f "$tmp" "$entry"
  # Older entries of the same tag are superseded (the tags have no '-').
  local base tag
  base="$(basename "$entry")"; tag="${base%%-*}"
  find "$(dirname "$entry")" -maxdepth 1 -name "$tag-*" ! -name "$base" ! -name '*.partial' -delete 2>/dev/null || true
}
