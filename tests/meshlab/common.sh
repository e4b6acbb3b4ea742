# Shared by the meshlabserver tests (sourced). Stages the plugin and runs meshlabserver under a
# virtual X server, since the 2020.09 server needs an OpenGL context even for non-GL filters.

fail() { echo "FAIL: $*" >&2; exit 1; }

# FCVT_MESHLAB_HOST=ROOT (the debian13 tests, tests/debian13.cmake): the same tests against
# MeshLab 2022.02 in the Debian 13 root ROOT, where fcvt-meshlab-host stands in for
# meshlabserver (tests/debian13/stage-host.sh) and the plugin is the one our .deb installed
# there (PLUGIN_SO is then unused).

# stage_meshlab STAGE_DIR PLUGIN_SO -> prints the staged meshlabserver path
stage_meshlab() {
  if [ -n "${FCVT_MESHLAB_HOST:-}" ]; then
    bash "$FCVT_SOURCE_DIR/tests/debian13/stage-host.sh" "$FCVT_MESHLAB_HOST" "$FCVT_SOURCE_DIR" "$1" >/dev/null \
      || fail "staging the MeshLab 2022.02 host in $1"
  else
    "$FCVT_SOURCE_DIR/scripts/stage-meshlab.sh" "$1" "$2" >/dev/null || fail "staging MeshLab in $1"
  fi
  echo "$1/bin/meshlabserver"
}

# run_meshlabserver SERVER LOG ARGS...: stdout (meshlabserver's log) to LOG, stderr to LOG.err;
# sets MLS_RC. timeout keeps a hung server from blocking CTest until its own timeout.
run_meshlabserver() {
  local server="$1" log="$2"
  shift 2
  set +e
  if [ -n "${FCVT_MESHLAB_HOST:-}" ]; then  # no display needed (Qt's offscreen platform)
    timeout 500 "$server" "$@" >"$log" 2>"$log.err"
  else
    timeout 500 xvfb-run -a "$server" "$@" >"$log" 2>"$log.err"
  fi
  MLS_RC=$?
  set -e
  echo "--- meshlabserver $* (exit $MLS_RC); log:"
  cat "$log"
  echo "--- stderr (last lines):"
  tail -n 15 "$log.err"
}

# The value of parameter NAME in the .mlx script FILE.
mlx_param() {
  sed -n "s/.*name=\"$2\"[^>]*value=\"\([^\"]*\)\".*/\1/p" "$1" | head -n 1
}

# The count of ELEMENT (vertex, face) in the header of the PLY file FILE.
ply_count() {
  head -c 4096 "$1" | tr -d '\r' | sed -n "s/^element $2 \\([0-9]*\\).*/\\1/p" | head -n 1
}

# mlx_with SCRIPT OUT N PARAM VALUE: the .mlx SCRIPT with vertexCount N and PARAM set to VALUE
# ("absent": PARAM left out of it) written to OUT; fails when the edit did not take.
mlx_with() {
  local script="$1" out="$2" n="$3" param="$4" value="$5"
  local args=(-e 's/\(name="vertexCount"[^>]*value="\)[^"]*"/\1'"$n"'"/')
  if [ "$value" = absent ]; then
    args+=(-e "/name=\"$param\"/d")
  else
    args+=(-e 's/\(name="'"$param"'"[^>]*value="\)[^"]*"/\1'"$value"'"/')
  fi
  sed "${args[@]}" "$script" > "$out"
  if [ "$value" = absent ]; then
    ! grep -q "name=\"$param\"" "$out" || fail "$out: $param still in the script"
  else
    grep -q "name=\"$param\" value=\"$value\"" "$out" || fail "$out: $param $value not set"
  fi
}
