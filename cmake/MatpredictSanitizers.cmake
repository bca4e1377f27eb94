# MATPREDICT_SANITIZE builds everything with ASan + UBSan; UBSan findings abort so tests fail on them.
if(MATPREDICT_SANITIZE)
  set(_san -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_compile_options(${_san})
  add_link_options(-fsanitize=address,undefined)
endif()

# MATPREDICT_FUZZ instruments everything for libFuzzer's coverage feedback (the fuzz targets
# themselves link -fsanitize=fuzzer, which brings libFuzzer's main).
if(MATPREDICT_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "MATPREDICT_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
