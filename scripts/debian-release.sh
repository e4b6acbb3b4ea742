# Sourced by scripts/package-debian.sh and tests/debian13/common.sh: what each newer Debian
# release the project packages for means. debian_release RELEASE sets
#   tag              the prefix of its root (BUILD/<tag>-root), results and CTest names
#   meshlab_release  the MeshLab version Debian ships there
#   meshlab_next     the first version after it (the package's upper bound)
# and returns 1 for a release it does not know.
debian_release() {
  case "$1" in
    trixie) tag=debian13; meshlab_release=2022.02; meshlab_next=2022.03 ;;
    forky) tag=forky; meshlab_release=2025.07; meshlab_next=2025.08 ;;
    *) return 1 ;;
  esac
}
