#!/usr/bin/env bash
# The filter's side files through meshlabserver 2020.09 (issue 50), where the filter itself reads
# the input's texture images by name and writes the baked one beside the input: a texture image
# that is a FIFO is a reason in the log (the atlas kept), never a hang; the baked image is written
# through no link (a dangling one, or one to another file) and over no existing file.
# Usage: side_files.sh SOURCE_DIR PLUGIN_SO WORK_DIR FCVT_CLI
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"; cli="$4"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out/fifo" "$work/out/links"
server="$(stage_meshlab "$work/stage" "$plugin")"
sed -e 's/\(name="vertexCount" value="\)[0-9]*"/\1800"/' "$FCVT_SOURCE_DIR/resources/fcvt-remesh.mlx" > "$work/out/remesh.mlx"
for d in fifo links; do
  cp "$FCVT_SOURCE_DIR/resources/textured/"{bunny10k_textured.obj,bunny10k_textured.mtl,TextureDouble_A.png} "$work/out/$d/"
  "$cli" convert "$work/out/$d/bunny10k_textured.obj" "$work/out/$d/bunny.ply" --quiet 2>/dev/null
done

# The image a FIFO: the filter reports why it keeps the atlas, and meshlabserver ends.
rm "$work/out/fifo/TextureDouble_A.png"
mkfifo "$work/out/fifo/TextureDouble_A.png"
run_meshlabserver "$server" "$work/out/fifo/log.txt" -i "$work/out/fifo/bunny.ply" -o "$work/out/fifo/out.ply" -m wt \
  -s "$work/out/remesh.mlx"
[ "$MLS_RC" -eq 0 ] || fail "FIFO image: meshlabserver exited with $MLS_RC"
grep -q "FCVT: new layer" "$work/out/fifo/log.txt" || fail "FIFO image: filter not run"
grep -q "FCVT: texture kept in the input's atlas.*FIFO" "$work/out/fifo/log.txt" \
  || fail "FIFO image: the log should keep the atlas and name the FIFO"

# The baked image's name taken by a dangling link and by a link to another file: neither written.
victim="$work/out/victim.png"
printf 'not an image to overwrite' > "$victim"
ln -s "$work/out/nowhere.png" "$work/out/links/bunny_FCVT_texture.png"
ln -s "$victim" "$work/out/links/bunny_FCVT_texture_2.png"
run_meshlabserver "$server" "$work/out/links/log.txt" -i "$work/out/links/bunny.ply" -o "$work/out/links/out.ply" -m wt \
  -s "$work/out/remesh.mlx"
[ "$MLS_RC" -eq 0 ] || fail "links: meshlabserver exited with $MLS_RC"
grep -q "FCVT: texture baked into 'bunny_FCVT_texture_3.png'" "$work/out/links/log.txt" \
  || fail "links: the baked image should take the first free name, bunny_FCVT_texture_3.png"
[ ! -e "$work/out/nowhere.png" ] || fail "links: written through the dangling link"
[ "$(cat "$victim")" = "not an image to overwrite" ] || fail "links: written through the link to another file"
[ -L "$work/out/links/bunny_FCVT_texture.png" ] && [ -L "$work/out/links/bunny_FCVT_texture_2.png" ] \
  || fail "links: a link was replaced"
[ -f "$work/out/links/bunny_FCVT_texture_3.png" ] && [ ! -L "$work/out/links/bunny_FCVT_texture_3.png" ] \
  || fail "links: the baked image is not a file of its own"
echo "side files: PASS"
