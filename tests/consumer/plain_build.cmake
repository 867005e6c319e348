# cmake -DSOURCE_DIR=<repo> -DWORK_DIR=... -DCXX=... -P plain_build.cmake  (CTest: consumer.plain_build)
# The README's C++ install commands as a user runs them, kept in step with it:
#   cmake -S . -B build                    (no options, on a machine without GoogleTest, pybind11 or
#                                           Google Benchmark, hidden here)
#   cmake --build build -j "$(nproc)"      (ProcessorCount: the CPUs available, as nproc counts them)
#   cmake --install build --prefix PREFIX
# then a program built against the installed compiled library with pkg-config. Checks that the
# configure chose a Release build and left tests, benchmarks and the Python module off.
cmake_minimum_required(VERSION 3.25)  # policies for script mode (IN_LIST)
file(REMOVE_RECURSE ${WORK_DIR})
set(build ${WORK_DIR}/build)
set(prefix ${WORK_DIR}/prefix)
function(run what)
  list(JOIN ARGN " " command)
  message(STATUS "${what}: ${command}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc})")
  endif()
endfunction()

run("configure" ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${build} -DCMAKE_CXX_COMPILER=${CXX}
    -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON)
file(STRINGS ${build}/CMakeCache.txt cache REGEX "^(CMAKE_BUILD_TYPE|BOXCYL_BUILD_[A-Z]+):")
foreach(expected "CMAKE_BUILD_TYPE:STRING=Release" "BOXCYL_BUILD_TESTS:BOOL=OFF" "BOXCYL_BUILD_BENCHMARKS:BOOL=OFF"
                 "BOXCYL_BUILD_PYTHON:BOOL=OFF")
  if(NOT expected IN_LIST cache)
    message(FATAL_ERROR "a configure without options should give ${expected}; the cache has: ${cache}")
  endif()
endforeach()
include(ProcessorCount)
ProcessorCount(jobs)
run("build" ${CMAKE_COMMAND} --build ${build} -j ${jobs})
run("install" ${CMAKE_COMMAND} --install ${build} --prefix ${prefix})
file(STRINGS ${build}/CMakeCache.txt libdir REGEX "^CMAKE_INSTALL_LIBDIR:")
string(REGEX REPLACE "^[^=]*=" "" libdir "${libdir}")
execute_process(COMMAND ${CMAKE_COMMAND} -DPREFIX=${prefix} -DLIBDIR=${libdir} -DPACKAGE=boxcyl
                        -DSOURCE=${CMAKE_CURRENT_LIST_DIR}/compiled.cpp -DOUTPUT=${WORK_DIR}/consumer -DCXX=${CXX}
                        -P ${CMAKE_CURRENT_LIST_DIR}/pkg_config.cmake
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the pkg-config consumer of the plain build failed (${rc})")
endif()
file(REMOVE_RECURSE ${WORK_DIR})
