#!/usr/bin/env bash
# Runs a command with DISPLAY set to a private Xvfb server of its own (a free display number,
# chosen by Xvfb itself with -displayfd, so parallel tests do not collide), then stops the server.
# Exit status 77 with a message when Xvfb is not installed (scripts/install-deps.sh installs it):
# the viewer's tests skip then.
set -u
if ! command -v Xvfb >/dev/null 2>&1; then
    echo "Xvfb is not installed (apt-get install xvfb): skipping"
    exit 77
fi
number_file=$(mktemp)
Xvfb -displayfd 3 -screen 0 1600x1200x24 -nolisten tcp 3>"$number_file" 2>/dev/null &
server=$!
for _ in $(seq 200); do
    grep -q . "$number_file" && break
    sleep 0.05
done
display=$(head -n 1 "$number_file")
rm -f "$number_file"
if [ -z "$display" ]; then
    kill "$server" 2>/dev/null
    echo "Xvfb did not start"
    exit 1
fi
unset WAYLAND_DISPLAY SDL_VIDEODRIVER
# Under AddressSanitizer, no leak check for the viewer's processes: SDL loads the X11 and D-Bus
# client libraries with dlopen and unloads them at SDL_Quit, and what they keep for the process's
# lifetime is then reported from unknown modules that no suppression can name. Memory errors are
# still caught; the rest of the suite keeps the leak check.
if [ -n "${ASAN_OPTIONS:-}" ] || [ -n "${LSAN_OPTIONS:-}" ]; then
    export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
fi
DISPLAY=":$display" "$@"
status=$?
kill "$server" 2>/dev/null
wait "$server" 2>/dev/null
exit $status
