#!/usr/bin/env bash
# Installs the build into a temporary prefix, then configures, builds and runs the consumer
# projects against it with find_package(matpredict). Usage: find_package_test.sh BUILD_DIR [FLAGS]
# FLAGS (e.g. the sanitizer flags of BUILD_DIR) are used to compile and link the consumer.
set -euo pipefail
build_dir=$1
flags=${2:-}
source_dir=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$source_dir/consumer" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" > "$work/configure.log"
cmake --build "$work/build" > "$work/build.log"
export LD_LIBRARY_PATH="$work/prefix/lib:$work/prefix/lib/x86_64-linux-gnu:${LD_LIBRARY_PATH:-}"
"$work/build/consumer"
mkdir "$work/variants"
"$work/build/material_variants" "$work/variants"
mkdir "$work/meshes"
"$work/build/prepare_mesh" "$work/meshes"
"$work/build/score_images"
"$work/build/predict_maps"
