# How zraster's libraries are assembled from its modules.
#
# A module is src/<name>/*.cpp compiled once as an object library. zraster_library() joins
# modules into an exported library (zraster_core, zraster_io); zraster_internal_library() gives
# the command, tests, benchmarks and fuzzers the same objects with every internal symbol
# reachable (a shared zraster_core exports only the public API).

# Flags for our own code only: warnings are errors, and no floating-point contraction, so that
# results do not depend on whether the compiler fuses a*b+c (determinism across builds and SIMD
# kernels, and the benchmark scene generators require it).
# Warnings are errors when zraster is the top-level project (its CI); a consumer building it as a
# subproject with another compiler or flags gets the warnings without failing on them.
add_library(zraster_flags INTERFACE)
target_compile_options(zraster_flags INTERFACE -Wall -Wextra -Wpedantic -ffp-contract=off
                                               $<$<BOOL:${ZRASTER_WARNINGS_AS_ERRORS}>:-Werror>)
target_compile_features(zraster_flags INTERFACE cxx_std_20)

# The GLM configuration the public headers are compiled with. It is a usage requirement of
# zraster::core, so a consumer never compiles GLM's types differently from the library.
set(ZRASTER_GLM_DEFINITIONS GLM_FORCE_XYZW_ONLY GLM_ENABLE_EXPERIMENTAL)

if(BUILD_SHARED_LIBS)
  set(CMAKE_POSITION_INDEPENDENT_CODE ON)
endif()

# zraster/version.hpp, generated from the project's version.
configure_file(${PROJECT_SOURCE_DIR}/cmake/version.hpp.in
               ${PROJECT_BINARY_DIR}/include/zraster/version.hpp @ONLY)

set(ZRASTER_INCLUDE_DIRS $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
                         $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/include>
                         $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)

# Under UndefinedBehaviorSanitizer, two checks multiply the compile time of the Highway kernels (a
# file compiled once per SIMD target) four to six times: pointer-overflow and object-size, most
# of a sanitizer build (shade_kernel.cpp: 150 s instead of 25 s at -O1). Those files alone are
# compiled without them; AddressSanitizer still checks every access they make (a superset of what
# object-size checks), and every other file keeps both.
function(zraster_relax_kernel_sanitizer_checks sources)
  if(NOT CMAKE_CXX_FLAGS MATCHES "-fsanitize=[^ ]*undefined")
    return()
  endif()
  foreach(source ${sources})
    file(STRINGS ${source} per_target_lines REGEX "hwy/foreach_target\\.h")
    if(per_target_lines)
      set_property(SOURCE ${source} APPEND PROPERTY COMPILE_OPTIONS
                                        -fno-sanitize=pointer-overflow,object-size)
    endif()
  endforeach()
endfunction()

# zraster_module(NAME [DEPS module...] [PRIVATE_DEPS target...]): the object library
# zraster_module_NAME of src/NAME/*.cpp. DEPS name the modules it builds on (the layering of
# docs/architecture.md); PRIVATE_DEPS the external libraries its sources use.
set_property(GLOBAL PROPERTY ZRASTER_MODULES "")
file(WRITE ${PROJECT_BINARY_DIR}/module_layers.txt "")
function(zraster_module name)
  cmake_parse_arguments(M "" "" "DEPS;PRIVATE_DEPS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${name}/*.cpp)
  set(target zraster_module_${name})
  add_library(${target} OBJECT ${sources})
  zraster_relax_kernel_sanitizer_checks("${sources}")
  target_include_directories(${target} PUBLIC ${ZRASTER_INCLUDE_DIRS}
                                       PRIVATE ${PROJECT_SOURCE_DIR}/src)
  target_compile_definitions(${target} PUBLIC ${ZRASTER_GLM_DEFINITIONS} PRIVATE ZRASTER_BUILDING)
  if(BUILD_SHARED_LIBS)
    target_compile_definitions(${target} PUBLIC ZRASTER_SHARED)
    set_target_properties(${target} PROPERTIES CXX_VISIBILITY_PRESET hidden
                                               VISIBILITY_INLINES_HIDDEN ON)
  endif()
  set(module_deps)
  foreach(dep ${M_DEPS})
    list(APPEND module_deps zraster_module_${dep})
  endforeach()
  target_link_libraries(${target} PUBLIC glm::glm ${module_deps}
                                  PRIVATE zraster_flags ${M_PRIVATE_DEPS})
  set_property(GLOBAL APPEND PROPERTY ZRASTER_MODULES ${name})
  # The layering the tests check on the sources (tests/layering/check_layering.sh).
  string(REPLACE ";" " " deps_line "${M_DEPS}")
  file(APPEND ${PROJECT_BINARY_DIR}/module_layers.txt "${name} ${deps_line}\n")
  set_property(GLOBAL PROPERTY ZRASTER_MODULE_DEPS_${name} "${M_DEPS}")
  set_property(GLOBAL PROPERTY ZRASTER_MODULE_EXTERNAL_${name} "${M_PRIVATE_DEPS}")
endfunction()

# zraster_library(NAME MODULES module... [DEPS target...] [PRIVATE_DEPS target...]): the
# exported library zraster_NAME (zraster::NAME) made of the modules' objects.
function(zraster_library name)
  cmake_parse_arguments(L "" "" "MODULES;DEPS;PRIVATE_DEPS" ${ARGN})
  set(target zraster_${name})
  add_library(${target})
  add_library(zraster::${name} ALIAS ${target})
  foreach(module ${L_MODULES})
    target_sources(${target} PRIVATE $<TARGET_OBJECTS:zraster_module_${module}>)
  endforeach()
  target_include_directories(${target} PUBLIC ${ZRASTER_INCLUDE_DIRS})
  target_compile_definitions(${target} PUBLIC ${ZRASTER_GLM_DEFINITIONS})
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_link_libraries(${target} PUBLIC glm::glm ${L_DEPS} PRIVATE ${L_PRIVATE_DEPS})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name}
                                             VERSION ${PROJECT_VERSION}
                                             SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
  if(BUILD_SHARED_LIBS)
    target_compile_definitions(${target} PUBLIC ZRASTER_SHARED)
    target_link_options(${target} PRIVATE -Wl,--no-undefined)
  endif()
  set_property(GLOBAL APPEND PROPERTY ZRASTER_LIBRARIES ${target})
endfunction()

# zraster_internal: the libraries as the repository's own programs link them. Static builds use
# zraster_core and zraster_io themselves; shared builds link the same objects statically, since
# the shared libraries hide the internal symbols tests and tools reach through src/ headers.
function(zraster_internal_library)
  add_library(zraster_internal INTERFACE)
  target_include_directories(zraster_internal INTERFACE ${PROJECT_SOURCE_DIR}/src)
  if(NOT BUILD_SHARED_LIBS)
    target_link_libraries(zraster_internal INTERFACE zraster_core zraster_io)
    return()
  endif()
  get_property(modules GLOBAL PROPERTY ZRASTER_MODULES)
  add_library(zraster_internal_objects STATIC)
  set(external)
  foreach(module ${modules})
    target_sources(zraster_internal_objects PRIVATE $<TARGET_OBJECTS:zraster_module_${module}>)
    get_property(deps GLOBAL PROPERTY ZRASTER_MODULE_EXTERNAL_${module})
    list(APPEND external ${deps})
  endforeach()
  list(REMOVE_DUPLICATES external)
  target_include_directories(zraster_internal_objects PUBLIC ${ZRASTER_INCLUDE_DIRS})
  target_compile_definitions(zraster_internal_objects PUBLIC ${ZRASTER_GLM_DEFINITIONS})
  target_link_libraries(zraster_internal_objects PUBLIC glm::glm ${external})
  target_link_libraries(zraster_internal INTERFACE zraster_internal_objects)
endfunction()
