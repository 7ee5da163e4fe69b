# Every public header includes Simbody through include/graspsim/simbody.h (which keeps Simbody's
# class layouts those of Debian's library whatever the includer's NDEBUG), never directly: a direct
# include would make Release builds of programs using the installed package disagree with
# libSimTKcommon. Run by ctest as: cmake -DINCLUDE_DIR=<source>/include -P <this>
cmake_minimum_required(VERSION 3.25)
file(GLOB_RECURSE headers ${INCLUDE_DIR}/graspsim/*.h)
set(direct)
foreach(header IN LISTS headers)
  if(header STREQUAL "${INCLUDE_DIR}/graspsim/simbody.h")
    continue()
  endif()
  file(STRINGS ${header} lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"](simbody/|SimTK)")
  if(lines)
    list(APPEND direct ${header})
  endif()
endforeach()
list(LENGTH headers count)
if(count LESS 10)
  message(FATAL_ERROR "simbody include check: found only ${count} headers under ${INCLUDE_DIR}/graspsim")
endif()
if(direct)
  list(JOIN direct "\n  " names)
  message(FATAL_ERROR "these headers include Simbody directly; include \"graspsim/simbody.h\" instead:\n  ${names}")
endif()
