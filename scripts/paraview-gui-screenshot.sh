#!/usr/bin/env bash
# paraview-gui-screenshot.sh [OUTPUT.png]
#
# Makes Documentation/images/paraview-gui.png: ParaView's GUI on a private
# Xvfb (1600x1000) runs ParaView/Examples/deepgi_gui_scene.py, then
# xdotool types "Deep GI" into the Properties panel's search box (which
# shows the view's Deep Global Illumination group), and xwd captures the
# screen. Needs the plugin built by `bash scripts/test.sh` and the packages
# xdotool and x11-apps (xwd), which only this script uses.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DEEPGI_BUILD_DIR:-$repo/build}"
output="${1:-$repo/Documentation/images/paraview-gui.png}"
for tool in Xvfb xdotool xwd paraview; do
  command -v "$tool" >/dev/null || { echo "$0: $tool is missing" >&2; exit 1; }
done

work="$(mktemp -d)"
Xvfb :97 -screen 0 1600x1000x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null; pkill -f "deepgi_gui_scene.py" 2>/dev/null; rm -rf "$work"' EXIT
export DISPLAY=:97
sleep 2

DEEPGI_PARAVIEW_PLUGIN="$build/paraview-plugin/install/lib/paraview-5.11/plugins/DeepGI/DeepGI.so" \
  DEEPGI_MESH="$repo/Testing/Data/meshes/bunny.ply" \
  PYTHONPATH="$build/python3-paraview/usr/lib/python3/dist-packages" \
  paraview --dr --script="$repo/ParaView/Examples/deepgi_gui_scene.py" >"$work/paraview.log" 2>&1 &
window=""
for _ in $(seq 120); do
  window="$(xdotool search --name "ParaView 5.11" 2>/dev/null | head -1)" && [[ -n "$window" ]] && break
  sleep 1
done
[[ -n "$window" ]] || { echo "$0: ParaView's window did not appear" >&2; exit 1; }
sleep 30 # the script: plugin, data, a converged still
xdotool windowsize "$window" 1600 1000
sleep 5
xdotool mousemove 130 538 click 1 # the Properties panel's search box
xdotool type --delay 100 "Deep GI"
sleep 5
xwd -root -silent >"$work/screen.xwd"
/usr/bin/python3 "$repo/scripts/xwd-to-png.py" "$work/screen.xwd" "$output"
echo "$output"
