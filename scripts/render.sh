#!/usr/bin/env bash
# Fresh Debian 12 to an image: installs packages, builds, renders the built-in default scene to
# zraster.png in the current directory. Extra arguments go to `zraster render`.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ZRASTER_BUILD_DIR:-$root/build}
bash "$root/scripts/build.sh" >/dev/null
"$build/zraster" render builtin:default -o zraster.png "$@"
echo "wrote $(pwd)/zraster.png"
