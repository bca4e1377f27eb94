# matpredict_library(TARGET SOURCES...): a library of the project, called from its folder
# (libmat<lib>/): matpredict::TARGET too, public headers in include/ (installed under the
# install prefix's include/), the sources and their own headers in src/, the project's warnings.
function(matpredict_library target)
  add_library(${target} ${ARGN})
  add_library(matpredict::${target} ALIAS ${target})
  target_include_directories(${target}
    PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  matpredict_warnings(${target})
endfunction()
