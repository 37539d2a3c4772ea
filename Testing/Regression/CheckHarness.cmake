# ctest case hov.RegressionHarness: the regression tests fail when they should.
# Runs the driver of Testing/Regression (DRIVER) on TestHOVBracketCPU:
#  1. as registered: passes;
#  2. with the opacity unit distance perturbed by 1% ("-perturb 0.01"): must
#     fail on the strict comparison, write the candidate and the difference image
#     (VTK's own comparison is reported; it lets such a change pass);
#  3. with a missing baseline, and 4. a baseline of another size: must fail with
#     a message saying so and write the candidate;
#  5. without a dataset: must fail with a message.
# Variables: DRIVER, DATA (Testing/Data), WORK_DIR.
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(test TestHOVBracketCPU)
set(data "${DATA}/bracket_tet4_ccx.vtu")
set(baseline "${DATA}/Baseline/${test}.png")

# run(<case> <expected: pass|fail> <text the output must contain or ""> <args...>)
function (run case expected text)
  set(dir "${WORK_DIR}/${case}")
  file(MAKE_DIRECTORY "${dir}")
  execute_process(COMMAND "${DRIVER}" ${test} -T "${dir}" ${ARGN}
    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
  message(STATUS "--- ${case}: exit code ${code}\n${out}${err}")
  if (expected STREQUAL "pass" AND NOT code EQUAL 0)
    message(FATAL_ERROR "${case}: expected to pass, exit code ${code}")
  elseif (expected STREQUAL "fail" AND (code EQUAL 0 OR NOT code MATCHES "^[0-9]+$"))
    message(FATAL_ERROR "${case}: expected a failure (non-zero exit code, no crash), got '${code}'")
  endif ()
  if (text AND NOT out MATCHES "${text}")
    message(FATAL_ERROR "${case}: the output does not say '${text}'")
  endif ()
  if (expected STREQUAL "fail" AND NOT EXISTS "${dir}/${test}.png" AND NOT case STREQUAL "no-data")
    message(FATAL_ERROR "${case}: no candidate image ${dir}/${test}.png written")
  endif ()
  set(output "${out}" PARENT_SCOPE)
endfunction ()

run(as-registered pass "strict comparison .*passed" -data "${data}" -V "${baseline}")
run(perturbed fail "strict comparison failed" -data "${data}" -V "${baseline}" -perturb 0.01)
if (NOT EXISTS "${WORK_DIR}/perturbed/${test}.strict-diff.png")
  message(FATAL_ERROR "perturbed: no difference image written")
endif ()
if (output MATCHES "VTK's comparison [^:]*: passed")
  message(STATUS "note: VTK's own comparison (threshold 0.15) passed the 1% perturbation")
endif ()
run(missing-baseline fail "baseline '.*' not found" -data "${data}"
  -V "${WORK_DIR}/no-such-baseline.png")
run(other-size fail "pixels, the rendered image 128 x 128" -data "${data}"
  -V "${DATA}/Baseline/TestHOVZooRayCast.png")
run(no-data fail "no dataset" -V "${baseline}")
message(STATUS "the regression harness fails on a perturbed rendering, a missing baseline, a "
  "baseline of another size and a missing dataset")
