# ctest case hov.Install: install the build tree into a fresh prefix, build a
# separate project against it with find_package(HighOrderVolume), run it, and
# import the Python package from the installed location.
# Variables: BUILD_DIR, CONSUMER_DIR, WORK_DIR, PYTHON, PYTHON_DEST; SANITIZE and
# PRELOAD in a sanitizer build (the consumer is built with the same runtime, python3
# gets it preloaded).
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${out}")
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "Command failed (${result}): ${ARGN}\n${out}\n${err}")
  endif ()
endfunction()

run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
set(consumer_flags)
set(python_env "PYTHONPATH=${prefix}/${PYTHON_DEST}")
if (SANITIZE)
  list(APPEND consumer_flags "-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined"
    "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
  list(APPEND python_env "LD_PRELOAD=${PRELOAD}" "ASAN_OPTIONS=detect_leaks=0")
endif ()
run("${CMAKE_COMMAND}" -S "${CONSUMER_DIR}" -B "${WORK_DIR}/consumer-build"
  -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}" "-DPython3_EXECUTABLE=${PYTHON}"
  ${consumer_flags})
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/consumer-build")
run("${WORK_DIR}/consumer-build/consumer")
run("${CMAKE_COMMAND}" -E env ${python_env} "${PYTHON}" -c
  "import highordervolume, os; m = highordervolume.vtkHighOrderVolumeMapper(); assert m.GetClassName() == 'vtkHighOrderVolumeMapper'; assert highordervolume.__file__.startswith(os.path.realpath('${prefix}')) or highordervolume.__file__.startswith('${prefix}'), highordervolume.__file__; print('python import OK from', highordervolume.__file__)")
