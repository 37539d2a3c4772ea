"""What every test_*.py shares (not a test itself: ctest runs test_*.py only): the record of
the checks, the two arguments ctest passes, the tools of the build tree the package was
imported from, and the exit status."""
import argparse
import os

import highordervolume

FAILURES = []


def check(ok, what):
    """Print the check's result; a failed one is recorded (the exit status of finish())."""
    print(("ok   " if ok else "FAIL ") + what, flush=True)
    if not ok:
        FAILURES.append(what)
    return ok


def arguments():
    """--data <test data dir> --temp <output dir>, as ctest passes them."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--data", required=True)
    parser.add_argument("--temp", required=True)
    return parser.parse_args()


def find_script(name):
    """bin/<name> of the build tree the package was imported from, or None."""
    d = os.path.dirname(os.path.abspath(highordervolume.__file__))
    for _ in range(6):
        d = os.path.dirname(d)
        cand = os.path.join(d, "bin", name)
        if os.path.isfile(cand):
            return cand
    return None


def finish():
    """The number of failed checks printed; the exit status (1 if any failed)."""
    print("%d failure(s)" % len(FAILURES))
    return 1 if FAILURES else 0
