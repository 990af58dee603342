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

# The Highway kernels: files that include hwy/foreach_target.h, which compiles the file once per
# SIMD target by including it again. They stay out of unity builds (CMAKE_UNITY_BUILD, which the
# scripts turn on: a file that re-includes itself cannot be pasted into another), and two
# sanitizer settings are relaxed for them alone:
# - under UndefinedBehaviorSanitizer, pointer-overflow and object-size multiply their compile time
#   four to six times (shade_kernel.cpp: 150 s instead of 25 s at -O1); AddressSanitizer still
#   checks every access they make (a superset of what object-size checks), and every other file
#   keeps both;
# - under AddressSanitizer (clang), their accesses are checked by calls into the runtime instead
#   of inlined checks (-asan-instrumentation-with-call-threshold=0): the same checks, made by
#   __asan_load/__asan_store, in a fifth of the compile time (visibility_kernel.cpp: 107 s
#   inlined, 22 s with calls).
function(zraster_mark_simd_kernels sources)
  set(sanitizer_options)
  if(CMAKE_CXX_FLAGS MATCHES "-fsanitize=[^ ]*undefined")
    list(APPEND sanitizer_options -fno-sanitize=pointer-overflow,object-size)
  endif()
  if(CMAKE_CXX_FLAGS MATCHES "-fsanitize=[^ ]*address" AND CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    # (Two words: a source's COMPILE_OPTIONS take no "SHELL:" group.)
    list(APPEND sanitizer_options -mllvm -asan-instrumentation-with-call-threshold=0)
  endif()
  foreach(source ${sources})
    file(STRINGS ${source} per_target_lines REGEX "hwy/foreach_target\\.h")
    if(per_target_lines)
      set_property(SOURCE ${source} PROPERTY SKIP_UNITY_BUILD_INCLUSION ON)
      if(sanitizer_options)
        set_property(SOURCE ${source} APPEND PROPERTY COMPILE_OPTIONS ${sanitizer_options})
      endif()
    endif()
  endforeach()
endfunction()

# zraster_unity_build(TARGET): batches of the target's sources compiled as one file when
# ZRASTER_UNITY_BUILD is on (the SIMD kernels excluded, zraster_mark_simd_kernels).
function(zraster_unity_build target)
  set_target_properties(${target} PROPERTIES UNITY_BUILD ${ZRASTER_UNITY_BUILD}
                                             UNITY_BUILD_BATCH_SIZE 8)
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
  zraster_mark_simd_kernels("${sources}")
  zraster_unity_build(${target})
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
