# The install test (ctest label install): installs the build to a temporary prefix, configures
# examples/ on its own against that prefix (find_package(graspsim)), builds two examples in Release, runs them,
# and checks what it wrote. Also checks that the exported targets carry none of the project's
# warning flags or NDEBUG handling. Run by ctest as: cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -P <this>
cmake_minimum_required(VERSION 3.25)
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR)
  if(NOT ${var})
    message(FATAL_ERROR "install test: -D${var}=... is required")
  endif()
endforeach()

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "install test: ${what} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "install test: ${what}: ok")
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
run_step("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

foreach(file bin/graspsim include/graspsim/opensim/osim_model.h lib/cmake/graspsim/graspsimConfig.cmake
             lib/cmake/graspsim/graspsimConfigVersion.cmake lib/cmake/graspsim/graspsimTargets.cmake
             share/graspsim/models/scenarios/phone-pinch.yaml share/graspsim/anthropometry/de_leva_1996_table4.csv)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "install test: ${prefix}/${file} was not installed")
  endif()
endforeach()
file(READ ${prefix}/lib/cmake/graspsim/graspsimTargets.cmake targets)
foreach(flag -Wall -Wextra -Wpedantic -Wshadow -fsanitize NDEBUG ${SOURCE_DIR} ${BUILD_DIR})
  string(FIND "${targets}" "${flag}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "install test: the exported targets mention '${flag}': the package must not impose it")
  endif()
endforeach()

set(launcher)
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run_step("configure examples/ against the installed package" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples
  -B ${WORK_DIR}/build -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix} ${launcher})
run_step("build build_and_export_model" ${CMAKE_COMMAND} --build ${WORK_DIR}/build --target build_and_export_model)
run_step("run build_and_export_model" ${WORK_DIR}/build/build_and_export_model ${WORK_DIR}/subject_arm)
file(READ ${WORK_DIR}/subject_arm.osim osim)
string(FIND "${osim}" "<OpenSimDocument Version=\"40000\">" at)
if(at EQUAL -1 OR NOT EXISTS ${WORK_DIR}/subject_arm.urdf)
  message(FATAL_ERROR "install test: the example did not write subject_arm.osim and subject_arm.urdf")
endif()
# A Release build (NDEBUG) of a program that runs Simbody through graspsim's headers, with no
# flag from the package: graspsim/simbody.h keeps Simbody's class layouts those of Debian's library.
run_step("build simulate_phone_pinch" ${CMAKE_COMMAND} --build ${WORK_DIR}/build --target simulate_phone_pinch)
run_step("run simulate_phone_pinch" ${WORK_DIR}/build/simulate_phone_pinch 0.2)
file(REMOVE_RECURSE ${WORK_DIR})
