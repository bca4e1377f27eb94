#!/usr/bin/env bash
# The optional fuzz tests: builds the readers of untrusted files with clang's libFuzzer, ASan and
# UBSan into ./build-fuzz and fuzzes each (PLY, OBJ, MTL, glTF, material folder, scene file,
# make_dataset's configuration, checkpoint) for
# MATPREDICT_FUZZ_SECONDS (default 60) from the seed corpus in tests/fuzz/corpus and the seeds
# the build makes. A crash, a sanitizer report or an exception other
# than std::runtime_error fails the test and leaves the input in build-fuzz/tests/fuzz.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/install_deps.sh"
sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
dpkg -s clang-14 libclang-rt-14-dev >/dev/null 2>&1 ||
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends clang-14 libclang-rt-14-dev
build="$root/build-fuzz"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
  -DMATPREDICT_FUZZ=ON -DMATPREDICT_BUILD_BENCH=OFF \
  -DMATPREDICT_FUZZ_SECONDS="${MATPREDICT_FUZZ_SECONDS:-60}"
cmake --build "$build" --target fuzz_ply fuzz_obj fuzz_mtl fuzz_gltf fuzz_material_folder fuzz_scene fuzz_dataset_config fuzz_checkpoint checkpoint_seed
ctest --test-dir "$build" -L fuzz --output-on-failure
