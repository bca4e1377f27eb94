#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds everything and runs the whole test suite.
# MATPREDICT_SANITIZE=1 builds with ASan + UBSan into ./build-sanitize instead;
# MATPREDICT_BLENDER_TESTS=1 also installs Blender 3.4 and runs the tests against Cycles;
# MATPREDICT_SLURM_TESTS=1 installs slurm-wlm and munge, so dataset.slurm runs instead of skipping.
# The matpredict Python package is registered for this user (scripts/register_python_package.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/install_deps.sh"
if [ "${MATPREDICT_SANITIZE:-0}" = 1 ]; then
  build="$root/build-sanitize"
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMATPREDICT_SANITIZE=ON -DMATPREDICT_BUILD_BENCH=OFF \
    -DMATPREDICT_BLENDER_TESTS="${MATPREDICT_BLENDER_TESTS:-0}"
else
  build="$root/build"
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMATPREDICT_BLENDER_TESTS="${MATPREDICT_BLENDER_TESTS:-0}"
fi
cmake --build "$build" -j "$(nproc)"
# `python3 -c "import matpredict"` from anywhere (not for the sanitizer's build, whose extension
# needs the sanitizer's runtime preloaded).
if [ "${MATPREDICT_SANITIZE:-0}" != 1 ]; then bash "$root/scripts/register_python_package.sh" "$build"; fi
ctest --test-dir "$build" --output-on-failure -j "$(nproc)"
