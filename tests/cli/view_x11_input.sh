#!/usr/bin/env bash
# Drives `zraster view` with real X11 input (xdotool through the XTEST extension), as a user's
# keyboard and mouse would, so that SDL's own event translation is exercised, not only --script.
# Run under tests/cli/with_xvfb.sh:  view_x11_input.sh ZRASTER SCENE SIZE
# Presses 1 (flat shading), drags with the right button (pan), turns the wheel one notch (zoom),
# waits, then presses q; the viewer writes view.png (--screenshot) in the working directory and
# prints its camera. Exit status 77 when xdotool is not installed (the test skips).
set -u
if ! command -v xdotool >/dev/null 2>&1; then
    echo "xdotool is not installed (apt-get install xdotool): skipping"
    exit 77
fi
zraster=$1 scene=$2 size=$3
"$zraster" view "$scene" --size "$size" --no-hud --screenshot view.png >viewer.txt 2>&1 &
viewer=$!
window=$(timeout 60 xdotool search --sync --name "zraster view" | head -n 1)
if [ -z "$window" ]; then
    kill "$viewer" 2>/dev/null
    echo "the viewer's window did not appear"
    cat viewer.txt
    exit 1
fi
xdotool windowfocus --sync "$window"
xdotool key 1
xdotool mousemove --window "$window" 40 30
xdotool mousedown 3 mousemove_relative --sync -- 12 -5 mouseup 3
xdotool click 4
# Time for the frame with the new state to be shown (a few milliseconds at this size, more under
# the sanitizers): the screenshot is the last frame displayed.
sleep 2
xdotool key q
wait "$viewer"
status=$?
cat viewer.txt
exit $status
