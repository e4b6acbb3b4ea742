#!/usr/bin/env bash
# Regenerates the README's pictures (docs/images/) and prints the figures of the meshes they
# show (fcvt metrics --json: V6%, Q_avg, theta_min).
#
# Usage: render_readme.sh BUILD_DIR [WORK_DIR]
#   BUILD_DIR  a build with the fcvt and filter_fcvt targets (cli/fcvt, filter_fcvt/libfilter_fcvt.so)
#   WORK_DIR   where the meshes and logs are kept (default: a temporary directory)
# Needs Debian's meshlab (the meshlab-isotropic row of fcvt compare, and the MeshLab
# picture), f3d, xvfb, x11-apps, x11-utils, xdotool; see scripts/render.py and
# scripts/render_meshlab.sh.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
[ $# -ge 1 ] || { sed -n '2,11p' "$0" >&2; exit 2; }
build="$(cd "$1" && pwd)"
fcvt="$build/cli/fcvt"
plugin="$build/filter_fcvt/libfilter_fcvt.so"
[ -x "$fcvt" ] || { echo "render_readme.sh: $fcvt not built" >&2; exit 1; }
if [ $# -ge 2 ]; then work="$2"; mkdir -p "$work"; else work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT; fi
work="$(cd "$work" && pwd)"
img="$here/docs/images"
mkdir -p "$img"
render() { python3 "$here/scripts/render.py" "$@"; }
figures() {  # MESH LABEL -> one line of the figures the README quotes
  "$fcvt" metrics "$1" --json | python3 -c '
import json, re, sys
m = json.load(sys.stdin)
head = open(sys.argv[2], "rb").read(2000).decode("ascii", "replace")
nv = re.search(r"element vertex (\d+)", head).group(1)
print("%-24s |X| %s  V6%% %.1f  Q_avg %.3f  theta_min %.1f  Q_min %.3f  %%<30 %.2f" % (
    sys.argv[1], nv, m["v6_pct"], m["q_avg"], m["theta_min"], m["q_min"], m["pct_lt30"]))' "$2" "$1"
}
echo "fcvt: $fcvt ($(git -C "$here" rev-parse --short HEAD), $(date -u +%FT%TZ))" | tee "$work/figures.txt"

# 1. bunny at 5000 vertices: CVT, FCVT (the default pipeline), MeshLab's isotropic remeshing.
"$fcvt" compare "$here/resources/bunny.obj" --vertices 5000 --save "$work/bunny" --json --quiet >"$work/bunny-compare.json"
render "$work/bunny-cvt.ply" --out "$img/bunny-cvt.png" --valence --dots 5
render "$work/bunny-fcvt.ply" --out "$img/bunny-fcvt.png" --valence --dots 5
render "$work/bunny-meshlab-isotropic.ply" --out "$img/bunny-meshlab.png" --valence --dots 5
# 2. The FCVT mesh again from fcvt remesh (same defaults and seed: the same mesh, with its
#    field), a close-up of the head with the field's crosses.
"$fcvt" remesh "$here/resources/bunny.obj" "$work/bunny-field.ply" --vertices 5000 --quiet
render "$work/bunny-field.ply" --out "$img/bunny-fcvt-field.png" --valence --dots 7 --field --zoom 2.5 --focus 0.25 0.62 0.5
# 3. The lambda sweep on fertility at 3000 vertices, without the valence optimisation (it
#    would hide what the field term does): lambda 0 with the pure-CVT schedule, 0.002, 0.01.
"$fcvt" remesh "$here/resources/fertility.off" "$work/fertility-lambda-0.ply" --vertices 3000 --lambda 0 \
  --lloyd-iterations 30 --cvt-iterations 130 --fcvt-iterations 0 --no-valence --quiet
for l in 0.002 0.01; do
  "$fcvt" remesh "$here/resources/fertility.off" "$work/fertility-lambda-$l.ply" --vertices 3000 --lambda "$l" --no-valence --quiet
done
for l in 0 0.002 0.01; do
  render "$work/fertility-lambda-$l.ply" --out "$img/fertility-lambda-$l.png" --valence --dots 4 --size 500 400 --view 30 20
done
# 4. Straight from MeshLab: the filter with its defaults, the quality report's colours.
bash "$here/scripts/render_meshlab.sh" "$here/resources/bunny.obj" "$img/bunny-meshlab-gui.png" --plugin "$plugin" \
  --ply "$work/bunny-meshlab-gui.ply" --log "$work/bunny-meshlab-gui.log"

{
  for m in cvt fcvt meshlab-isotropic field meshlab-gui; do
    figures "$work/bunny-$m.ply" "bunny-$m"
  done
  for l in 0 0.002 0.01; do
    figures "$work/fertility-lambda-$l.ply" "fertility-lambda-$l"
  done
  grep -m1 "FCVT quality: Q_min" "$work/bunny-meshlab-gui.log" | sed 's/^.*FCVT quality: /MeshLab log: /'
} | tee -a "$work/figures.txt"
ls -l "$img"
