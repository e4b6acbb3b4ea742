#!/usr/bin/env bash
# OBJ -> OFF for the meshlabserver tests. Why: MeshLab 2020.09's OBJ importer asserts (abort,
# exit 134) on resources/torus.obj, so the test feeds meshlabserver an OFF copy of the same
# geometry. Handles "v x y z [w]", "f a b c ..." with a/b/c, a//c and negative indices (faces
# with more than three corners are written as polygons, which the OFF importer triangulates),
# CRLF line endings; ignores everything else.
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 IN.obj OUT.off" >&2; exit 2; }
awk '
  { sub(/\r$/, "") }
  $1 == "v" { nv++; vx[nv] = $2; vy[nv] = $3; vz[nv] = $4; next }
  $1 == "f" {
    if (NF < 4) { printf "obj2off: line %d: face with fewer than 3 corners\n", NR > "/dev/stderr"; exit 1 }
    nf++; line = NF - 1
    for (k = 2; k <= NF; k++) {
      split($k, parts, "/"); i = parts[1] + 0
      if (i < 0) i = nv + 1 + i
      if (i < 1 || i > nv) { printf "obj2off: line %d: vertex index %s out of range\n", NR, $k > "/dev/stderr"; exit 1 }
      line = line " " (i - 1)
    }
    faces[nf] = line; next
  }
  END {
    if (nv == 0 || nf == 0) { print "obj2off: no vertices or faces" > "/dev/stderr"; exit 1 }
    print "OFF"; print nv, nf, 0
    for (i = 1; i <= nv; i++) print vx[i], vy[i], vz[i]
    for (i = 1; i <= nf; i++) print faces[i]
  }
' "$1" > "$2.tmp"
mv -f "$2.tmp" "$2"
