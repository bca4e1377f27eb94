# Every dependency is a Debian 12 package (scripts/install_deps.sh installs them).
find_package(embree 3.13 REQUIRED CONFIG)
find_package(TBB REQUIRED CONFIG)
find_package(glm REQUIRED CONFIG)
find_package(TinyGLTF REQUIRED CONFIG)
find_package(tinyobjloader REQUIRED CONFIG)
find_package(Eigen3 3.3 REQUIRED CONFIG)
find_package(nlohmann_json REQUIRED CONFIG)
find_package(fmt REQUIRED CONFIG)
find_package(CLI11 REQUIRED CONFIG)
find_package(yaml-cpp REQUIRED CONFIG)
find_package(Torch REQUIRED CONFIG)
find_package(ZLIB REQUIRED)

# OpenImageIO's CMake config references /usr/bin/iconvert and /usr/include/opencv4 on Debian 12,
# so it is found through pkg-config, which has no such quirks.
find_package(PkgConfig REQUIRED)
pkg_check_modules(OpenImageIO REQUIRED IMPORTED_TARGET OpenImageIO)
# stb's image resampler (libstb-dev), for material maps of other sizes than their set's.
pkg_check_modules(stb REQUIRED IMPORTED_TARGET stb)

if(MATPREDICT_BUILD_TESTS)
  find_package(Catch2 2.13 REQUIRED CONFIG)
endif()

# OpenCV's core and image processing (GrabCut, connected components) from Debian's
# libopencv-imgproc-dev, found by hand: OpenCV's CMake config and pkg-config file come only with
# libopencv-dev, which pulls in VTK, Open MPI and FFmpeg for modules matpredict does not use.
find_path(OpenCV_IMGPROC_INCLUDE_DIR opencv2/imgproc.hpp PATH_SUFFIXES opencv4 REQUIRED)
find_library(OpenCV_CORE_LIBRARY opencv_core REQUIRED)
find_library(OpenCV_IMGPROC_LIBRARY opencv_imgproc REQUIRED)
add_library(matpredict_opencv_imgproc INTERFACE IMPORTED)
target_include_directories(matpredict_opencv_imgproc SYSTEM INTERFACE ${OpenCV_IMGPROC_INCLUDE_DIR})
target_link_libraries(matpredict_opencv_imgproc INTERFACE ${OpenCV_IMGPROC_LIBRARY} ${OpenCV_CORE_LIBRARY})
