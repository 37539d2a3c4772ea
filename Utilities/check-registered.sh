#!/usr/bin/env bash
# Fails (exit 1) if any of the given ctest labels has no registered test in
# the current build directory: a test program whose tests were not registered
# (a lost gtest_discover_tests, a test directory left out) would otherwise
# let the suite pass with a whole group of tests missing. Used by test.sh and
# sanitize.sh:  check-registered.sh kernels cxx ...
set -euo pipefail
missing=0
for label in "$@"; do
  n=$(ctest -N -L "^${label}\$" | sed -n 's/^Total Tests: //p')
  if [ "${n:-0}" -eq 0 ]; then
    echo "check-registered.sh: no test labelled '$label' is registered" >&2
    missing=1
  fi
done
exit $missing
