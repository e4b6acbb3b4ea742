# Sourced by the scripts that drive the MeshLab GUI under Xvfb (scripts/render_meshlab.sh,
# tests/meshlab/gui_field_dialog.sh).
# wait_meshlab_window PID: prints the id of MeshLab's main window once it is mapped (at most
# 60 s), nothing if the process PID ends first or no window comes.
wait_meshlab_window() {
  local pid="$1" wid=""
  for _ in $(seq 1 120); do
    wid="$(xdotool search --name '^MeshLab 20' 2>/dev/null | head -n 1)"
    [ -n "$wid" ] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.5
  done
  echo "$wid"
}
