#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine and renders the embedded default into ./render_out/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/install_deps.sh"
bash "$root/scripts/build.sh"
"$root/build/apps/render_object/render_object" "$@"
