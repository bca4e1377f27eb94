#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds make_dataset and renders its embedded default (6
# built-in objects x 3 library materials x 8 views of the paper's camera grid, pixel-aligned maps,
# about a minute on 2 cores) into ./dataset_out/, checks it with --verify and draws its contact
# sheets into ./dataset_out/preview/index.html. The matpredict Python package is built and
# registered for this user too, so that `python3 -c "import matpredict"` works.
# Arguments go to make_dataset (try --help).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/install_deps.sh"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release
targets=(make_dataset render_object)
if grep -q '^MATPREDICT_PYTHON:BOOL=ON' "$root/build/CMakeCache.txt"; then targets+=(matpredict_python); fi
cmake --build "$root/build" --target "${targets[@]}" -j "$(nproc)"
bash "$root/scripts/register_python_package.sh" "$root/build"
"$root/build/apps/make_dataset/make_dataset" "$@"
if [ "$#" -eq 0 ]; then
  "$root/build/apps/make_dataset/make_dataset" --verify dataset_out
  "$root/build/apps/make_dataset/make_dataset" --preview dataset_out
fi
