"""hov-convergence (highordervolume.convergence) on the bundled bracket at 128x128.

Study 'resample' (vtkResampleToImage at 16 and 32 points + vtkGPUVolumeRayCastMapper against
our GPU-compatible accurate image) through `python -m`, and study 'ugrc-sample' (the
unstructured ray caster's image sample distance 2 and 1) through the console script
bin/hov-convergence. Checks: CSV and PNG written; the CSV parses; each max/mean/p99 error
equals the one recomputed here from the written float images (within 1e-6); the fitted orders
are finite and equal the least-squares slope recomputed here from the CSV's costs and errors.
"""
import csv
import math
import os
import subprocess
import sys

import numpy as np

import highordervolume

from hov_pytest import arguments, check, FAILURES, find_script


def check_study(out, study, n_values):
    csv_path = os.path.join(out, "convergence_%s.csv" % study)
    png_path = os.path.join(out, "convergence_%s.png" % study)
    for p in (csv_path, png_path):
        check(os.path.isfile(p) and os.path.getsize(p) > 0, "%s written" % os.path.basename(p))
    if not os.path.isfile(csv_path):
        return
    with open(csv_path) as f:
        rows = list(csv.DictReader(f))
    check(len(rows) == n_values, "%s: %d rows" % (study, len(rows)))
    reference = np.load(os.path.join(out, "convergence_%s_reference.npy" % study)).astype(np.float64)
    check(reference.max() > 0.2, "%s: reference image is not blank" % study)
    for r in rows:
        check(r["status"].startswith("ok"), "%s %s: status %s" % (study, r["value"], r["status"]))
        image = np.load(os.path.join(out, r["image"])).astype(np.float64)
        diff = np.abs(image - reference).reshape(-1, 3)
        got = {"max_err": diff.max(), "mean_err": diff.mean(axis=0).mean(),
               "p99_err": np.percentile(diff, 99.0, axis=0).max()}
        dev = max(abs(float(r[k]) - v) for k, v in got.items())
        check(dev <= 1e-6, "%s %s: CSV errors = recomputed from the .npy (deviation %.2e)"
              % (study, r["value"], dev))
        check(0.0 < float(r["max_err"]) <= 1.0, "%s %s: 0 < max error <= 1" % (study, r["value"]))
        check(float(r["cost_time_s"]) > 0.0 and float(r["cost_samples"]) > 0.0,
              "%s %s: positive costs" % (study, r["value"]))
    for cost, col in (("cost_time_s", "order_time"), ("cost_samples", "order_samples")):
        x = np.log([float(r[cost]) for r in rows])
        y = np.log([float(r["max_err"]) for r in rows])
        slope = np.polyfit(x, y, 1)[0]
        order = float(rows[0][col])
        check(math.isfinite(order) and abs(order - slope) <= 1e-9 * max(1.0, abs(slope)),
              "%s: fitted %s %.4f finite, = slope recomputed from the CSV %.4f"
              % (study, col, order, slope))
    print("  %s: %s" % (study, ", ".join("%s -> max %s" % (r["value"], r["max_err"]) for r in rows)))


def main():
    args = arguments()
    data = os.path.join(args.data, "bracket_tet4_ccx.vtu")
    out = os.path.join(args.temp, "test_convergence_tool")
    common = [data, "von_mises", "--out", out, "--size", "128", "128", "--frames", "1"]
    proc = subprocess.run([sys.executable, "-m", "highordervolume.convergence"] + common
                          + ["--study", "resample", "--values", "16,32"],
                          capture_output=True, text=True, timeout=300)
    print(proc.stdout[-2000:])
    print(proc.stderr[-2000:], file=sys.stderr)
    check(proc.returncode == 0, "hov-convergence --study resample exits with 0")
    check_study(out, "resample", 2)

    script = find_script("hov-convergence")
    check(script is not None, "bin/hov-convergence exists beside the package's build tree")
    if script:
        proc = subprocess.run([script] + common + ["--study", "ugrc-sample", "--values", "2,1",
                                                   "--cost", "time"],
                              capture_output=True, text=True, timeout=300)
        print(proc.stdout[-2000:])
        print(proc.stderr[-2000:], file=sys.stderr)
        check(proc.returncode == 0, "bin/hov-convergence --study ugrc-sample exits with 0")
        check_study(out, "ugrc-sample", 2)

    if FAILURES:
        print("%d check(s) failed" % len(FAILURES))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
