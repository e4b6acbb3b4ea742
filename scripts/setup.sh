#!/usr/bin/env bash
# Installs everything FCVT needs on a Debian bookworm machine (run as root). Idempotent:
# packages already present are skipped by apt, and the MeshLab source tree is fetched once
# into third_party/meshlab-src (ignored by git).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
export DEBIAN_FRONTEND=noninteractive

packages=(
  build-essential cmake pkg-config dpkg-dev
  libeigen3-dev liblbfgspp-dev libnanoflann-dev libcgal-dev
  qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev libglew-dev libglu1-mesa-dev
  libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev libstb-dev
  meshlab xvfb xauth python3 debootstrap zstd
  x11-apps x11-utils
  f3d optipng pngquant xdotool
  clang libclang-rt-14-dev libomp-dev clang-format
  pybind11-dev python3-dev python3-numpy python3-meshio
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

# deb-src for bookworm main, needed by `apt-get source meshlab`.
src_list=/etc/apt/sources.list.d/fcvt-deb-src.sources
need_update=0
if ! grep -rqs '^Types:.*deb-src' /etc/apt/sources.list.d/ && ! grep -qs '^deb-src' /etc/apt/sources.list; then
  # The archive address is the one this machine's apt already uses (scripts/apt-archive.sh).
  archive="$(bash "$here/scripts/apt-archive.sh" bookworm)"
  printf 'Types: deb-src\nURIs: %s\nSuites: bookworm\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
    "$archive" > "$src_list"
  need_update=1
fi

if [ ${#missing[@]} -gt 0 ] || [ $need_update -eq 1 ] || [ ! -d "$here/third_party/meshlab-src" ]; then
  apt-get update -qq
fi
if [ ${#missing[@]} -gt 0 ]; then
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# MeshLab 2020.09 plugin headers and the matching vcglib (Debian's source package).
if [ ! -f "$here/third_party/meshlab-src/src/common/interfaces.h" ]; then
  mkdir -p "$here/third_party"
  tmp="$(mktemp -d)"
  (cd "$tmp" && apt-get source -qq --download-only meshlab && dpkg-source -x --no-check meshlab_*.dsc meshlab-src >/dev/null)
  rm -rf "$here/third_party/meshlab-src"
  mv "$tmp/meshlab-src" "$here/third_party/meshlab-src"
  rm -rf "$tmp"
fi
echo "setup: all dependencies present"
