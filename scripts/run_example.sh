#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds render_object and renders the embedded default (a
# built-in textured vase under the paper's light rig, grid cell (5, 16)) into ./render_out/.
# Arguments go to render_object (try --help).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/install_deps.sh"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$root/build" --target render_object -j "$(nproc)"
"$root/build/apps/render_object/render_object" "$@"
