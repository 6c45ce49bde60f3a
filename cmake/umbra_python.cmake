# The Python module's dependencies (python/): Debian's Python 3 with its
# development files, numpy and pybind11 (python3-dev, python3-numpy,
# pybind11-dev). Sets UMBRA_PYTHON_FOUND. Debian's interpreter comes first:
# a python3 earlier on PATH (pyenv) lacks the Debian modules the tests use.
if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python_EXECUTABLE /usr/bin/python3)
endif()
find_package(Python 3 COMPONENTS Interpreter Development.Module QUIET)
set(UMBRA_PYTHON_FOUND OFF)
if(Python_FOUND)
  set(PYBIND11_FINDPYTHON ON)
  find_package(pybind11 CONFIG QUIET)
  if(pybind11_FOUND)
    set(UMBRA_PYTHON_FOUND ON)
  endif()
endif()
if(UMBRA_PYTHON_FOUND)
  message(STATUS "Python module: ${Python_EXECUTABLE} ${Python_VERSION}, pybind11 ${pybind11_VERSION}")
else()
  message(STATUS "Python module: not built (apt-get install python3-dev pybind11-dev python3-numpy)")
endif()
