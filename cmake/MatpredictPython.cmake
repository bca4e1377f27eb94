# The Python package (python/) is built where Debian's Python 3 and pybind11 are found
# (python3-dev, pybind11-dev; python3-numpy at run time). Debian's /usr/bin/python3 is preferred
# over another python3 first on PATH (pyenv, a venv): its site-packages hold numpy and torch as
# Debian packages them, and it is the one `cmake --install` installs for.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python the matpredict package is built for")
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module)
if(Python3_FOUND)
  find_package(pybind11 2.10 CONFIG)
endif()
set(_python_found OFF)
if(Python3_FOUND AND pybind11_FOUND)
  set(_python_found ON)
endif()
option(MATPREDICT_PYTHON "Build the matpredict Python package (needs python3-dev and pybind11-dev)" ${_python_found})
if(MATPREDICT_PYTHON AND NOT _python_found)
  message(FATAL_ERROR "MATPREDICT_PYTHON is on but Python 3 (python3-dev) or pybind11 (pybind11-dev) was not found")
endif()
# Where Debian's python3 finds packages installed under the prefix: /usr/local/lib/python3.11/dist-packages.
set(MATPREDICT_PYTHON_INSTALL_DIR "lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/dist-packages"
    CACHE STRING "Where `cmake --install` puts the matpredict package, relative to the prefix")
