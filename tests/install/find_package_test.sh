#!/usr/bin/env bash
# Installs the build into a temporary prefix, then configures, builds and runs the consumer
# projects against it with find_package(matpredict), and imports the Python package from it. Usage: find_package_test.sh BUILD_DIR [FLAGS]
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
# The Python package, when built, imports from the prefix with Debian's python3 and no library
# path: the extension and the libraries find each other through their RUNPATHs.
# The installed apps run with no library path: their RUNPATH finds the libraries.
for app in render_object make_dataset train_regressor train_denoiser evaluate; do
  "$work/prefix/bin/$app" --help > /dev/null
done
for package in "$work"/prefix/lib/python3*/dist-packages; do
  [ -d "$package/matpredict" ] || continue
  PYTHONPATH="$package" /usr/bin/python3 -c \
    "import matpredict, sys; sys.exit(0 if matpredict.__file__.startswith('$package') and matpredict.aov_names() else 1)"
done
export LD_LIBRARY_PATH="$work/prefix/lib:$work/prefix/lib/x86_64-linux-gnu:${LD_LIBRARY_PATH:-}"
"$work/build/consumer"
mkdir "$work/variants"
"$work/build/material_variants" "$work/variants"
mkdir "$work/meshes"
"$work/build/prepare_mesh" "$work/meshes"
"$work/build/score_images"
"$work/build/predict_maps"
