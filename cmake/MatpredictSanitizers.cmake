# MATPREDICT_SANITIZE builds everything with ASan + UBSan; UBSan findings abort so tests fail on them.
if(MATPREDICT_SANITIZE)
  set(_san -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_compile_options(${_san})
  add_link_options(-fsanitize=address,undefined)
endif()
