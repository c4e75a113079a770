# The layer check (cmake/check_layers.cmake) on small trees written here, in WORK: it passes a tree whose
# includes go to the same layer or down, and fails, naming the file, the line and both folders, on an
# include of a higher layer; it also fails on a relative include and on a folder that is not a layer.
#
#   cmake -DCHECKER=<check_layers.cmake> -DWORK=<scratch folder> -P test_check_layers.cmake

if(NOT DEFINED CHECKER OR NOT DEFINED WORK)
  message(FATAL_ERROR "test_check_layers.cmake: give -DCHECKER=<check_layers.cmake> and -DWORK=<folder>")
endif()
set(layers "low,mid,high")

# write_tree(<name> <file> <variable> [<file> <variable>]...): a fresh tree WORK/<name>, each file holding
# the value of its variable (contents with ';' or '[' cannot travel in an argument list themselves).
function(write_tree name)
  file(REMOVE_RECURSE "${WORK}/${name}")
  set(args ${ARGN})
  while(args)
    list(POP_FRONT args file var)
    file(WRITE "${WORK}/${name}/${file}" "${${var}}")
  endwhile()
endfunction()

# run_check(<name> <expected exit code> [<text the output must hold>]...)
function(run_check name expected_rc)
  execute_process(COMMAND ${CMAKE_COMMAND} -DROOT=${WORK}/${name} -DLAYERS=${layers} -P ${CHECKER}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(all "${out}${err}")
  if(NOT rc EQUAL expected_rc)
    message(FATAL_ERROR "tree '${name}': the check exited with ${rc}, expected ${expected_rc}; it said:\n${all}")
  endif()
  # CMake wraps a long FATAL_ERROR message at spaces, where depends on the length of the paths in it: the
  # texts are looked for with every run of white space made one space.
  string(REGEX REPLACE "[ \t\r\n]+" " " flat "${all}")
  foreach(text IN LISTS ARGN)
    string(REGEX REPLACE "[ \t\r\n]+" " " text "${text}")
    string(FIND "${flat}" "${text}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "tree '${name}': the check's output lacks '${text}'; it said:\n${all}")
    endif()
  endforeach()
  message(STATUS "tree '${name}': exit ${rc} as expected")
endfunction()

set(low_hpp "#pragma once\n#include <vector>\n")
set(mid_hpp "#pragma once\n#include \"symcontact/low/a.hpp\"\n")
set(high_hpp "#pragma once\n")
# Lines with '[', ']', ';' and '\\' (characters with a meaning in CMake lists) before an include: they must
# not shift the line numbers.
set(special "int a[2]; char b = '\\\\';\n")
set(high_cpp "#include \"symcontact/high/c.hpp\"\n${special}#include \"symcontact/mid/b.hpp\"\n")

write_tree(clean low/a.hpp low_hpp mid/b.hpp mid_hpp high/c.hpp high_hpp high/c.cpp high_cpp)
run_check(clean 0 "4 files follow the order low < mid < high")

# The same tree with one upward include, on line 3 of low/a.hpp.
set(low_up_hpp "#pragma once\n${special}#include \"symcontact/mid/b.hpp\"\n")
write_tree(upward low/a.hpp low_up_hpp mid/b.hpp mid_hpp high/c.hpp high_hpp high/c.cpp high_cpp)
run_check(upward 1
          "${WORK}/upward/low/a.hpp:3: low includes mid (\"symcontact/mid/b.hpp\"), a layer above it"
          "1 violation(s)")

# Two layers up, from a source file.
set(low_cpp "#include \"symcontact/low/a.hpp\"\n#include \"symcontact/high/c.hpp\"\n")
write_tree(two_up low/a.hpp low_hpp low/a.cpp low_cpp high/c.hpp high_hpp)
run_check(two_up 1 "${WORK}/two_up/low/a.cpp:2: low includes high")

# A relative include would go around the check.
set(mid_relative_hpp "#pragma once\n#include \"../high/c.hpp\"\n")
write_tree(relative low/a.hpp low_hpp mid/b.hpp mid_relative_hpp high/c.hpp high_hpp)
run_check(relative 1 "${WORK}/relative/mid/b.hpp:2: includes \"../high/c.hpp\"")

# A folder that is not in the order.
write_tree(unknown low/a.hpp low_hpp extra/d.hpp high_hpp)
run_check(unknown 1 "folder 'extra' is not a layer")
