# Whether to build the Python module (python/), decided before the engine's modules are defined:
# the extension links zraster statically, so every object going into it must be compiled as
# position-independent code.
#
# Debian's interpreter is the default: its numpy and pybind11 are the packages
# scripts/install-deps.sh installs, while a python3 earlier on PATH (pyenv, a virtualenv) may lack
# them. -DPython_EXECUTABLE=... picks another.
#
# Sanitizer builds leave it out: an instrumented extension cannot load into an uninstrumented
# interpreter.
set(zraster_python_default OFF)
if(PROJECT_IS_TOP_LEVEL AND ZRASTER_BUILD_IO AND ZRASTER_BUILD_TOOLS
   AND NOT CMAKE_CXX_FLAGS MATCHES "-fsanitize")
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python the zraster module is built for")
  endif()
  find_package(Python 3.8 COMPONENTS Interpreter Development.Module NumPy QUIET)
  if(Python_FOUND)
    find_package(pybind11 2.6 CONFIG QUIET)
  endif()
  if(Python_FOUND AND pybind11_FOUND)
    set(zraster_python_default ON)
  endif()
endif()
option(ZRASTER_BUILD_PYTHON "Build the Python module (needs pybind11 and numpy)"
       ${zraster_python_default})

if(ZRASTER_BUILD_PYTHON)
  if(NOT ZRASTER_BUILD_IO OR NOT ZRASTER_BUILD_TOOLS)
    message(FATAL_ERROR "the Python module needs ZRASTER_BUILD_IO and ZRASTER_BUILD_TOOLS")
  endif()
  find_package(Python 3.8 REQUIRED COMPONENTS Interpreter Development.Module NumPy)
  find_package(pybind11 2.6 CONFIG REQUIRED)
  # -fPIC for the static libraries the extension links. Without semantic interposition the
  # compiler may still inline and call our own functions directly, as in a -fPIE build.
  set(CMAKE_POSITION_INDEPENDENT_CODE ON)
  target_compile_options(zraster_flags INTERFACE -fno-semantic-interposition)
  message(STATUS "zraster: Python module for ${Python_EXECUTABLE} (${Python_VERSION})")
elseif(PROJECT_IS_TOP_LEVEL)
  message(STATUS "zraster: no Python module (ZRASTER_BUILD_PYTHON is off: pybind11 or numpy "
                 "missing, or a sanitizer build)")
endif()
