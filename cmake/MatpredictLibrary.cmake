# matpredict_library(TARGET SOURCES...): a library of the project, called from its folder
# (libmat<lib>/): matpredict::TARGET too, public headers in include/ (installed under the
# install prefix's include/), the sources and their own headers in src/, the project's warnings.
# Installed, each library finds the others beside it ($ORIGIN), whatever the prefix: the Python
# package loads them from its own folder's RUNPATH, which the loader does not pass on.
function(matpredict_library target)
  add_library(${target} ${ARGN})
  add_library(matpredict::${target} ALIAS ${target})
  target_include_directories(${target}
    PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  set_target_properties(${target} PROPERTIES INSTALL_RPATH "$ORIGIN")
  matpredict_warnings(${target})
endfunction()
