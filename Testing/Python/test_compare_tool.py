"""hov-compare (highordervolume.compare) on two bundled datasets of the demo: the bracket at
128x128 (our CPU references in both opacity semantics, one OPENGL_PROJECTION method, RAY_CAST,
VTK's three unstructured mappers on the tetrahedra, the GPU route at one resample resolution)
and the mixed-cell zoo at 64x64 (our CPU reference and projection on the native cells, VTK's
projected tetrahedra on the tessellation). Runs the module with `python -m` and checks: every
output file exists; the CSV and Markdown tables parse and list the same methods; every error
in both tables equals the error recomputed here from the written float images (.npy) against
the reference image of its semantics (max / mean / p99 per channel, within 1e-6); the
reference rows have zero error, RAY_CAST on the bracket's linear tetrahedra too, the others
do not; the progress display printed one line per method. Then runs the installed-
style console script bin/hov-compare --list.
"""
import csv
import os
import subprocess
import sys

import numpy as np

import highordervolume
from highordervolume import compare_report

from hov_pytest import arguments, check, FAILURES, find_script


def recomputed(out, row, reference):
    image = np.load(os.path.join(out, row["image"])).astype(np.float64)
    diff = np.abs(image - reference).reshape(-1, 3)
    return {"max": diff.max(axis=0), "mean": diff.mean(axis=0),
            "p99": np.percentile(diff, 99.0, axis=0)}


def run_case(args, data, array, size, extra, expected, tag):
    """Runs hov-compare on one dataset and checks its outputs (see the file doc)."""
    out = os.path.join(args.temp, "test_compare_tool_" + tag)
    cmd = [sys.executable, "-m", "highordervolume.compare", data, array, "--out", out,
           "--size", str(size), str(size), "--frames", "1"] + extra
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    print(proc.stdout[-3000:])
    print(proc.stderr[-3000:], file=sys.stderr)
    check(proc.returncode == 0, "%s: hov-compare exits with 0 (got %d)" % (tag, proc.returncode))
    for key in expected:
        check(any(ln.startswith("[") and " %s " % key in ln and "100%" in ln
                  for ln in proc.stdout.splitlines()), "%s: progress line for %s" % (tag, key))
    for name in ["compare_montage.png", "compare_table.csv", "compare_table.md"] + \
            ["compare_%s.png" % k for k in expected] + ["compare_%s.npy" % k for k in expected]:
        path = os.path.join(out, name)
        check(os.path.isfile(path) and os.path.getsize(path) > 0, "%s: %s written" % (tag, name))
    if FAILURES:
        return

    with open(os.path.join(out, "compare_table.csv")) as f:
        rows = list(csv.DictReader(f))
    check([r["key"] for r in rows] == expected, "%s: CSV lists the methods in order: %s"
          % (tag, [r["key"] for r in rows]))
    with open(os.path.join(out, "compare_table.md")) as f:
        md_rows = {r["key"]: r for r in compare_report.parse_markdown_table(f.read())}
    check(sorted(md_rows) == sorted(expected), "%s: Markdown table lists the same methods" % tag)

    refs = {}
    for r in rows:
        check(r["status"].startswith("ok"), "%s: %s status ok (%s)" % (tag, r["key"], r["status"]))
        for field in ("prep_s", "first_render_s", "frame_s", "data_mib"):
            check(float(r[field]) >= 0.0, "%s: %s %s parses and is >= 0" % (tag, r["key"], field))
        # The resident-memory change may be negative (pages returned to the
        # system during the run, seen once at load 10): it must be a number.
        check(np.isfinite(float(r["rss_delta_mib"])),
              "%s: %s rss_delta_mib parses and is finite" % (tag, r["key"]))
        ref_key = r["reference"]
        if ref_key not in refs:
            refs[ref_key] = np.load(os.path.join(out, "compare_%s.npy" % ref_key)).astype(np.float64)
        reference = refs[ref_key]
        got = recomputed(out, r, reference)
        worst = 0.0
        for stat in ("max", "mean", "p99"):
            table = np.array([float(r["%s_%s" % (stat, c)]) for c in "rgb"])
            worst = max(worst, np.abs(table - got[stat]).max())
            md = np.array([float(v) for v in md_rows[r["key"]]["%s err R/G/B" % stat].split("/")])
            worst = max(worst, np.abs(md - got[stat]).max())
        check(worst <= 1e-6, "%s: %s: CSV and Markdown errors = recomputed from the .npy "
              "(max deviation %.2e)" % (tag, r["key"], worst))
        maxerr = max(float(r["max_%s" % c]) for c in "rgb")
        if r["key"].startswith("hov_cpu_"):
            check(ref_key == r["key"] and maxerr == 0.0, "%s: %s is its own reference, zero error"
                  % (tag, r["key"]))
        elif r["key"].startswith("hov_ray_") and tag == "bracket":
            # Linear tetrahedra: the ray caster's image equals the exact CPU image.
            check(maxerr <= 1e-6, "%s: %s equals %s (max %.2e)" % (tag, r["key"], ref_key, maxerr))
        else:
            check(0.0 < maxerr <= 1.0, "%s: %s differs from %s (max %.4f)"
                  % (tag, r["key"], ref_key, maxerr))
        if r["key"].startswith("hov_") or r["key"].startswith("vtk_gpu"):
            want = "hov_cpu_gpu" if r["key"].startswith("vtk_gpu") or r["key"].endswith("_gpu") \
                else "hov_cpu_vtk"
        else:
            want = "hov_cpu_vtk"
        check(ref_key == want, "%s: %s compared with the reference of its semantics (%s)"
              % (tag, r["key"], ref_key))
    # The reference images are not blank (a blank pair would compare equal).
    check(refs["hov_cpu_vtk"].max() > 0.2, "%s: reference image is not blank" % tag)


def main():
    args = arguments()
    data = os.path.join(args.data, "bracket_tet4_ccx.vtu")
    run_case(args, data, "von_mises", 128,
             ["--resolutions", "32", "--methods", "hov_proj_m1_vtk,hov_ray_vtk,vtk_*"],
             ["hov_cpu_vtk", "hov_proj_m1_vtk", "hov_ray_vtk", "hov_cpu_gpu", "vtk_pt",
              "vtk_ugrc", "vtk_zsweep", "vtk_gpu_32"], "bracket")
    # The mixed-cell zoo of the demo (tetrahedra, hexahedra, wedges, pyramids): our modes on
    # the native cells, VTK's projected tetrahedra on its tessellation.
    run_case(args, os.path.join(args.data, "zoo_mixed_ccx.vtu"), "temperature", 64,
             ["--resolutions", "16", "--semantics", "vtk", "--methods", "hov_proj_m1_vtk,vtk_pt"],
             ["hov_cpu_vtk", "hov_proj_m1_vtk", "vtk_pt"], "zoo")

    script = find_script("hov-compare")
    check(script is not None, "bin/hov-compare exists beside the package's build tree")
    if script:
        proc = subprocess.run([script, data, "von_mises", "--list"], capture_output=True,
                              text=True, timeout=120)
        check(proc.returncode == 0 and "vtk_zsweep" in proc.stdout and "hov_cpu_gpu" in proc.stdout,
              "hov-compare --list runs and lists the methods")

    if FAILURES:
        print("%d check(s) failed" % len(FAILURES))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
