#!/usr/bin/env bash
# Builds the Debian package of the MeshLab plugin for a newer Debian than this Debian 12 machine,
# as root:
#
#   bash scripts/package-debian.sh trixie|forky OUTDIR
#
#   trixie: Debian 13, MeshLab 2022.02 -> OUTDIR/meshlab-plugin-fcvt_<version>+deb13_amd64.deb
#   forky:  Debian testing (and sid), MeshLab 2025.07 -> ..._<version>+deb14_amd64.deb
#   each depending on exactly that MeshLab release (meshlab (>= X~), meshlab (<< X+1 month)).
#
# 1. a root of that release, made with debootstrap in BUILD/<tag>-root (BUILD: $FCVT_BUILD_DIR,
#    default build/; tag: debian13 or forky), from the archive this machine's apt already uses
#    (scripts/apt-archive.sh); build dependencies and the release's MeshLab installed by apt;
# 2. that MeshLab's plugin headers and vcglib from the release's `meshlab` source package
#    (apt-get source inside the root; when the archive serves only the .orig tarball, that
#    tarball, unpacked without Debian's patches: the script says which it used);
# 3. the core and the plugin built inside the root against them (the FilterPlugin API) and
#    linked to the release's libmeshlab-common;
# 4. the .deb in OUTDIR.
#
# A complete root from an earlier run is reused (the marker BUILD/<tag>-root/.fcvt-ready);
# FCVT_DEBIAN13_FRESH=1 (or FCVT_DEBIAN_FRESH=1) makes a new one: a copy of the cached root
# (scripts/root-cache.sh: /var/cache/fcvt-roots, keyed by release, archive and package list;
# FCVT_ROOT_CACHE=off disables it) when there is one, else with debootstrap and apt, which then
# fills the cache. Everything else stays inside BUILD. Exit status 77 (what CTest counts as skipped) when not run as
# root or when debootstrap fails (e.g. no network).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
[ $# -eq 2 ] || { echo "usage: $0 trixie|forky OUTDIR" >&2; exit 2; }
release="$1"
source "$here/scripts/debian-release.sh"
source "$here/scripts/root-cache.sh"
debian_release "$release" || { echo "package-debian: unknown release '$release' (trixie or forky)" >&2; exit 2; }
mkdir -p "$2"
out="$(cd "$2" && pwd)"
build="${FCVT_BUILD_DIR:-$here/build}"
mkdir -p "$build"
build="$(cd "$build" && pwd)"
root="$build/$tag-root"
d13build="$build/$tag-build"   # the in-root build tree (same path inside the root)
export DEBIAN_FRONTEND=noninteractive

skip() { echo "package-debian $release: SKIP: $*" >&2; exit 77; }
step_start=0
step() { step_start=$(date +%s); echo "== package-debian $release: $*"; }
step_done() { echo "   done in $(( $(date +%s) - step_start )) s"; }

[ "$(id -u)" -eq 0 ] || skip "needs root (debootstrap and chroot)"
command -v debootstrap >/dev/null || apt-get install -y -qq --no-install-recommends debootstrap >/dev/null \
  || skip "debootstrap is not installed and could not be installed"
in_root() { bash "$here/scripts/debian13-chroot.sh" "$root" --bind "$here" --bind "$build" -- "$@"; }

packages=(
  build-essential cmake pkg-config dpkg-dev xz-utils
  libeigen3-dev liblbfgspp-dev libnanoflann-dev libcgal-dev
  qtbase5-dev libqt5opengl5-dev libglew-dev libglu1-mesa-dev
  meshlab xvfb xauth x11-apps x11-utils xdotool
  # meshlab's Recommends that its own plugins link (an ordinary apt install brings them):
  # without them MeshLab skips filter_func ("Conditional Face Selection"), filter_qhull, ...
  lib3ds-1-3 libgmp10 libgomp1 libmpfr6 libmuparser2v5 libopenctm1 libqhull-r8.0 libxerces-c3.2t64
)

# The MeshLab's headers and vcglib: the release's meshlab source package, in the root's
# /usr/src/meshlab.
src="$root/usr/src/meshlab"
fetch_meshlab_source() {
  step "apt-get source meshlab ($release)"
  rm -rf "$root/usr/src/meshlab-get" "$src"
  mkdir -p "$root/usr/src/meshlab-get"
  chmod 777 "$root/usr/src/meshlab-get"   # apt's download sandbox user writes here
  set +e
  in_root sh -c 'cd /usr/src/meshlab-get && apt-get source -qq --download-only meshlab' \
    >"$build/$tag-source.log" 2>&1
  rc=$?
  set -e
  get="$root/usr/src/meshlab-get"
  dsc="$(ls "$get"/meshlab_*.dsc 2>/dev/null | head -n 1 || true)"
  orig="$(ls "$get"/meshlab_*.orig.tar.* 2>/dev/null | head -n 1 || true)"
  if [ "$rc" -eq 0 ] && [ -n "$dsc" ]; then
    in_root sh -c "cd /usr/src/meshlab-get && dpkg-source -x --no-check $(basename "$dsc") /usr/src/meshlab" >/dev/null
    echo "   MeshLab source: the Debian source package $(basename "$dsc") (Debian patches applied)"
  elif [ -n "$orig" ]; then
    mkdir -p "$src"
    tar -xf "$orig" -C "$src" --strip-components=1
    echo "   MeshLab source: apt-get source could not fetch the whole package (exit $rc; see" \
         "$build/$tag-source.log); using its upstream tarball $(basename "$orig"), without Debian's patches"
  else
    cat "$build/$tag-source.log" >&2
    echo "package-debian: apt-get source meshlab fetched neither the package nor its tarball" >&2
    exit 1
  fi
  [ -f "$src/src/common/plugins/interfaces/filter_plugin.h" ] \
    || { echo "package-debian: no MeshLab $meshlab_release plugin headers in $src" >&2; exit 1; }
  step_done
}

make_root() {
  rm -rf "$root"
  step "debootstrap $release into $root"
  # Debian 12's debootstrap has no script named forky: testing is made as sid is.
  script=""
  [ -e "/usr/share/debootstrap/scripts/$release" ] || script=/usr/share/debootstrap/scripts/sid
  debootstrap --variant=minbase "$release" "$root" "$archive" $script >"$build/$tag-debootstrap.log" 2>&1 || {
    tail -n 20 "$build/$tag-debootstrap.log" >&2
    rm -rf "$root"
    skip "debootstrap failed (log: $build/$tag-debootstrap.log)"
  }
  step_done
  printf 'Types: deb deb-src\nURIs: %s\nSuites: %s\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
    "$archive" "$release" > "$root/etc/apt/sources.list.d/debian.sources"
  # A testing archive's Release file carries a Valid-Until date; a mirror kept as of a day (as
  # this machine's may be) would be refused after it.
  echo 'Acquire::Check-Valid-Until "false";' > "$root/etc/apt/apt.conf.d/99fcvt-valid-until"
  rm -f "$root/etc/apt/sources.list"
  step "apt-get install ${#packages[@]} packages (MeshLab $meshlab_release, build dependencies, Xvfb) in the root"
  in_root apt-get update -qq
  in_root apt-get install -y -qq --no-install-recommends "${packages[@]}" >"$build/$tag-apt.log" 2>&1 || {
    tail -n 30 "$build/$tag-apt.log" >&2; echo "package-debian: apt-get install failed in the root" >&2; exit 1; }
  step_done
  fetch_meshlab_source
  in_root apt-get clean   # the downloaded .debs: not needed again, and not worth caching
  touch "$root/.fcvt-ready"
}

fresh="${FCVT_DEBIAN_FRESH:-${FCVT_DEBIAN13_FRESH:-0}}"
if [ "$fresh" = 1 ] || [ ! -e "$root/.fcvt-ready" ]; then
  archive="$(bash "$here/scripts/apt-archive.sh" "$release")" || skip "no Debian archive in this machine's apt sources"
  entry=""
  root_cache_enabled && entry="$(root_cache_entry "$tag" "$release" "$archive" "${packages[@]}")"
  if [ -n "$entry" ] && root_cache_fresh "$entry"; then
    step "unpack the cached $release root $entry"
    root_cache_restore "$entry" "$root"
    step_done
  else
    make_root
    if [ -n "$entry" ]; then
      step "cache the root as $entry"
      root_cache_save "$root" "$entry" || echo "   (could not write the cache; going on)"
      step_done
    fi
  fi
fi
# A root made by an earlier version of this list gets what the list has gained since.
missing=()
for p in "${packages[@]}"; do
  in_root dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  step "apt-get install ${missing[*]} in the root"
  in_root apt-get update -qq
  in_root apt-get install -y -qq --no-install-recommends "${missing[@]}" >>"$build/$tag-apt.log" 2>&1 || {
    tail -n 30 "$build/$tag-apt.log" >&2; echo "package-debian: apt-get install failed in the root" >&2; exit 1; }
  step_done
fi
echo "MeshLab in the root: $(in_root dpkg-query -W -f='${Version}' meshlab)"

[ -f "$src/src/common/plugins/interfaces/filter_plugin.h" ] || fetch_meshlab_source

step "build the core and the plugin inside the root (MeshLab $meshlab_release, FilterPlugin API)"
in_root cmake -S "$here" -B "$d13build" -DCMAKE_BUILD_TYPE=Release \
  -DFCVT_BUILD_CLI=OFF -DFCVT_BUILD_TESTS=OFF -DFCVT_BUILD_BENCH=OFF \
  -DFCVT_MESHLAB_SOURCE_DIR=/usr/src/meshlab -DFCVT_MESHLAB_API=2022 >"$build/$tag-cmake.log" 2>&1 || {
  cat "$build/$tag-cmake.log" >&2; exit 1; }
in_root cmake --build "$d13build" -j "$(nproc)" --target filter_fcvt
step_done

step "cpack"
rm -rf "$d13build/cpack"
in_root sh -c "cd '$d13build' && cpack -G DEB -B '$d13build/cpack'" >"$build/$tag-cpack.log" 2>&1 || {
  cat "$build/$tag-cpack.log" >&2; exit 1; }
deb="$(ls "$d13build"/cpack/meshlab-plugin-fcvt_*_amd64.deb)"
cp -f "$deb" "$out/"
step_done
echo "package-debian $release: $out/$(basename "$deb")"
echo "Depends: $(dpkg-deb -f "$deb" Depends)"
