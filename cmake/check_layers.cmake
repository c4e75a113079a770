# The layer check of src/symcontact/ (cmake -P): every file's quoted includes against the layer order.
#
#   cmake -DROOT=<dir> -DLAYERS=core,mesh,... -P check_layers.cmake
#
# ROOT holds one folder per layer (src/symcontact); LAYERS is their order, lowest first (src/CMakeLists.txt
# passes SYMCONTACT_LAYERS, comma-separated). A file of folder F may include "symcontact/G/..." only when G
# is F or comes before F. Every quoted include must be spelled "symcontact/<folder>/<file>" (a relative path
# would escape the check), and every folder must be a layer. Fails (exit 1) with one line per violation:
#   <file>:<line>: <F> includes <G> ("symcontact/G/x.hpp"), a layer above it (order: core < mesh < ...)
# Angle-bracket includes (the standard library, Eigen, Gmsh, ...) are not ours and are not looked at.

if(NOT DEFINED ROOT OR NOT DEFINED LAYERS)
  message(FATAL_ERROR "check_layers.cmake: give -DROOT=<folder of the layers> and -DLAYERS=<a,b,...>")
endif()
string(REPLACE "," ";" layers "${LAYERS}")
string(REPLACE ";" " < " order "${layers}")
get_filename_component(root "${ROOT}" ABSOLUTE)

set(violations "")
file(GLOB_RECURSE files RELATIVE "${root}" "${root}/*.hpp" "${root}/*.cpp" "${root}/*.h" "${root}/*.cc")
list(SORT files)
foreach(rel IN LISTS files)
  string(REGEX REPLACE "/.*" "" folder "${rel}")
  if(folder STREQUAL rel)
    list(APPEND violations "${root}/${rel}: outside every layer folder (${order})")
    continue()
  endif()
  list(FIND layers "${folder}" rank)
  if(rank EQUAL -1)
    list(APPEND violations "${root}/${rel}: folder '${folder}' is not a layer (${order}); add it to SYMCONTACT_LAYERS")
    continue()
  endif()
  # One list element per line, empty lines kept (foreach IN LISTS visits them): the characters with a
  # meaning in CMake lists (';', '[', ']', '\') are replaced first.
  file(READ "${root}/${rel}" text)
  string(REGEX REPLACE "[][;\\]" "_" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(line_no 0)
  foreach(line IN LISTS lines)
    math(EXPR line_no "${line_no} + 1")
    if(NOT line MATCHES "^[ \t]*#[ \t]*include[ \t]*\"([^\"]*)\"")
      continue()
    endif()
    set(path "${CMAKE_MATCH_1}")
    if(NOT path MATCHES "^symcontact/([^/]+)/[^/]")
      list(APPEND violations
           "${root}/${rel}:${line_no}: includes \"${path}\": spell our headers \"symcontact/<folder>/<file>\"")
      continue()
    endif()
    set(target "${CMAKE_MATCH_1}")
    list(FIND layers "${target}" target_rank)
    if(target_rank EQUAL -1)
      list(APPEND violations "${root}/${rel}:${line_no}: includes \"${path}\": '${target}' is not a layer (${order})")
    elseif(target_rank GREATER rank)
      list(APPEND violations
           "${root}/${rel}:${line_no}: ${folder} includes ${target} (\"${path}\"), a layer above it (order: ${order})")
    endif()
  endforeach()
endforeach()

list(LENGTH files num_files)
if(violations)
  list(LENGTH violations n)
  string(REPLACE ";" "\n" report "${violations}")
  message("${report}")
  message(FATAL_ERROR "layer check of ${root}: ${n} violation(s) of the layer order in ${num_files} files")
endif()
message(STATUS "layer check of ${root}: ${num_files} files follow the order ${order}")
