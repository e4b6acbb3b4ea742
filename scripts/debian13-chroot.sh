#!/usr/bin/env bash
# Runs a command inside the Debian 13 root (Debian 13 or forky) made by scripts/package-debian.sh, as root:
#
#   debian13-chroot.sh ROOT [--bind DIR]... -- CMD ARGS...
#
# The command runs in private mount and PID namespaces (unshare): /proc, /dev and /dev/shm are
# mounted for it and every DIR given with --bind appears inside the root at the same path as
# outside (so paths given to CMD mean the same file on both sides). Nothing is mounted on the
# host: the mounts go away with the namespace, and so does every process CMD leaves behind
# (an Xvfb, say) when CMD exits.
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: $0 ROOT [--bind DIR]... -- CMD ARGS..." >&2; exit 2; }
root="$(cd "$1" && pwd)"
shift
binds=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
  case "$1" in
    --bind) binds+=("$(cd "$2" && pwd)"); shift 2 ;;
    *) echo "debian13-chroot: unknown option $1" >&2; exit 2 ;;
  esac
done
[ "${1:-}" = "--" ] || { echo "debian13-chroot: missing -- before the command" >&2; exit 2; }
shift
[ -x "$root/bin/sh" ] || { echo "debian13-chroot: $root is not a Debian root" >&2; exit 1; }

# The inner script runs in the new namespaces, before the chroot. It stays the namespace's
# PID 1 and runs CMD as its child: as PID 1 itself, CMD would not get signals it relies on
# (xvfb-run waits for Xvfb's SIGUSR1).
inner='
set -e
root="$1"; shift
n="$1"; shift
for _ in $(seq 1 "$n"); do
  d="$1"; shift
  mkdir -p "$root$d"
  mount --bind "$d" "$root$d"
done
mount -t proc proc "$root/proc"
mount --rbind /dev "$root/dev"
mkdir -p "$root/dev/shm" && mount -t tmpfs -o mode=1777 tmpfs "$root/dev/shm"
chroot "$root" /usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
  HOME=/root LANG=C.UTF-8 DEBIAN_FRONTEND=noninteractive "$@"
rc=$?   # (a last command would be exec-ed by bash, and become PID 1)
exit $rc
'
exec unshare --mount --propagation private --pid --fork \
  bash -c "$inner" inner "$root" "${#binds[@]}" "${binds[@]}" "$@"
