# hov.RemoteModule (see CMakeLists.txt). Variables: REPOSITORY, WRAPPER, WORK_DIR, GENERATOR, CTEST.
file(REMOVE_RECURSE "${WORK_DIR}")
set(src "${WORK_DIR}/src")
set(module "${src}/Remote/HighOrderVolume")
file(MAKE_DIRECTORY "${module}")
configure_file("${WRAPPER}" "${src}/CMakeLists.txt" COPYONLY)

# The repository as VTK's remote fetch leaves it (a checkout in Remote/<name>):
# every top-level entry but build trees and git metadata.
file(GLOB entries RELATIVE "${REPOSITORY}" "${REPOSITORY}/*" "${REPOSITORY}/.ci")
foreach (entry IN LISTS entries)
  if (NOT entry MATCHES "^(build|_install|\\.git$)")
    file(COPY "${REPOSITORY}/${entry}" DESTINATION "${module}")
  endif ()
endforeach ()

function (run step)
  string(TIMESTAMP t0 "%s")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(TIMESTAMP t1 "%s")
  math(EXPR seconds "${t1} - ${t0}")
  string(LENGTH "${out}" n)
  if (n GREATER 6000)
    math(EXPR start "${n} - 6000")
    string(SUBSTRING "${out}" ${start} 6000 out)
  endif ()
  message(STATUS "--- ${step} (${seconds} s): exit code ${code}\n${out}\n${err}")
  if (NOT code EQUAL 0)
    message(FATAL_ERROR "${step} failed")
  endif ()
endfunction ()

# Unoptimised: this checks the build, not the speed (the strict image
# comparison holds at any optimisation level: the kernels are compiled without
# contraction, and their only fused multiply-adds are explicit std::fma, the
# same at any -O).
run(configure "${CMAKE_COMMAND}" -S "${src}" -B "${WORK_DIR}/build" -G "${GENERATOR}"
  -DCMAKE_BUILD_TYPE= -DPython3_EXECUTABLE=/usr/bin/python3)
cmake_host_system_information(RESULT cores QUERY NUMBER_OF_LOGICAL_CORES)
run(build "${CMAKE_COMMAND}" --build "${WORK_DIR}/build" --target hovRegressionTests
  --parallel ${cores})
run(test "${CTEST}" --test-dir "${WORK_DIR}/build" --output-on-failure
  -R "Cxx-(TestHOVBracketCPU|TestHOVZooProjection)$")
message(STATUS "the repository configures, builds and passes its regression tests as a VTK "
  "remote module (one vtk.module)")
