#!/usr/bin/env bash
# Installs exactly the Debian 12 packages matpredict builds and tests with.
set -euo pipefail

# What the CMake build finds (cmake/MatpredictDependencies.cmake, MatpredictPython.cmake), and the
# toolchain; the Python package's build and tests (pybind11, numpy, pytest); the tests'
# independent references (Python's scikit-image, Pillow, torchvision, OpenImageIO's EXR reader; a
# real browser for make_dataset's preview page); blender-data for its eight CC0 HDR environments
# (data only, it depends on python3 alone; matrender/builtin_environments.h).
packages=(
  build-essential cmake ninja-build pkg-config
  libembree-dev libtbb-dev libglm-dev libeigen3-dev
  libopenimageio-dev
  libtinygltf-dev libtinyobjloader-dev libstb-dev nlohmann-json3-dev libcli11-dev libfmt-dev libyaml-cpp-dev
  libtorch-dev libopenblas0-openmp zlib1g-dev libopencv-imgproc-dev
  catch2
  python3-skimage python3-pil python3-torch python3-torchvision
  python3-dev pybind11-dev python3-numpy python3-pytest python3-openimageio
  chromium
  blender-data
)
# Blender 3.4 is a reference for the optional tests against Cycles, never a build dependency.
if [ "${MATPREDICT_BLENDER_TESTS:-0}" = 1 ]; then packages+=(blender); fi
# A real cluster scheduler for the optional test of make_dataset's Slurm array script.
if [ "${MATPREDICT_SLURM_TESTS:-0}" = 1 ]; then packages+=(slurm-wlm munge); fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
echo "install_deps: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
