# Installs the package into a scratch prefix, moves the prefix elsewhere (the installed package
# must be relocatable: no path of the build machine in it), then:
#  - runs the installed command-line program (bin/measured_parameterization) on a small mesh;
#  - configures, builds and runs a separate project (test/downstream) that finds the package
#    with find_package(), with the component Cholmod when the package has it (WITH_CHOLMOD);
#  - checks that asking for a component that is not there fails cleanly: an unknown component,
#    and Cholmod when its library cannot be found.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... [-DWITH_CHOLMOD=ON] [-DWITH_CLI=ON]
#         [-DCGAL_DIR=...] -P downstream_check.cmake
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK_DIR}/install-prefix"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "install failed")
endif()
# relocatable: the package works from wherever the prefix is moved
file(RENAME "${WORK_DIR}/install-prefix" "${WORK_DIR}/prefix")
set(prefix "${WORK_DIR}/prefix")
file(GLOB_RECURSE package_files "${prefix}/*.cmake")
foreach(f IN LISTS package_files)
  file(READ "${f}" text)
  foreach(absolute "${WORK_DIR}" "${BUILD_DIR}" "${SOURCE_DIR}" "/usr/lib" "/usr/include")
    string(FIND "${text}" "${absolute}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "the installed ${f} holds the absolute path ${absolute}")
    endif()
  endforeach()
endforeach()

# the installed command-line program
if(WITH_CLI)
  set(cli "${prefix}/bin/measured_parameterization")
  if(NOT EXISTS "${cli}")
    message(FATAL_ERROR "cmake --install did not install ${cli}")
  endif()
  file(WRITE "${WORK_DIR}/square.off"
       "OFF\n5 4 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0.2\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n")
  execute_process(COMMAND "${cli}" "${WORK_DIR}/square.off" "${WORK_DIR}/square_uv.obj"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT EXISTS "${WORK_DIR}/square_uv.obj")
    message(FATAL_ERROR "the installed program failed (${rc}): ${out}${err}")
  endif()
  message(STATUS "installed program: ${out}")
endif()

# mbp_configure(DIR RESULT OUTPUT ARGS...): configures the downstream project in WORK_DIR/DIR
function(mbp_configure dir result output)
  # the same CGAL as the package was built with (CGAL 5.5 or the unpacked CGAL 6)
  set(cgal)
  if(CGAL_DIR)
    set(cgal "-DCGAL_DIR=${CGAL_DIR}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE_DIR}/test/downstream" -B "${WORK_DIR}/${dir}"
                          -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}" ${cgal} ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(${result} ${rc} PARENT_SCOPE)
  set(${output} "${out}${err}" PARENT_SCOPE)
endfunction()

if(WITH_CHOLMOD)
  set(cholmod_option -DWITH_CHOLMOD=ON)
else()
  set(cholmod_option -DWITH_CHOLMOD=OFF)
endif()
mbp_configure(build rc out ${cholmod_option})
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the downstream project failed:\n${out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK_DIR}/build" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the downstream project failed")
endif()
execute_process(COMMAND "${WORK_DIR}/build/consumer" RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the downstream program failed: ${out}")
endif()
message(STATUS "downstream program: ${out}")

# a component that is not there: configuring fails, naming it
mbp_configure(unknown rc out -DWITH_UNKNOWN_COMPONENT=ON)
if(rc EQUAL 0 OR NOT out MATCHES "No_such_component")
  message(FATAL_ERROR "asking for an unknown component did not fail cleanly:\n${out}")
endif()
# Cholmod asked for where CHOLMOD cannot be found: configuring fails, naming the component
mbp_configure(no-cholmod rc out -DWITH_CHOLMOD=ON
              "-DMeasuredParameterization_CHOLMOD_LIBRARY=${WORK_DIR}/no-such-dir/libcholmod.so")
if(rc EQUAL 0 OR NOT out MATCHES "component Cholmod not found")
  message(FATAL_ERROR "asking for Cholmod without CHOLMOD did not fail cleanly:\n${out}")
endif()
message(STATUS "downstream: package, component Cholmod (${WITH_CHOLMOD}), missing components: all as expected")
