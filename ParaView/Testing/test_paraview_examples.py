"""hov.ParaView.Examples: the pvbatch examples in ParaView/Examples run as documented (one
rank, and two ranks for the MPI example) and write their images: the Accurate Volume and
ParaView's Volume screenshots are not empty and agree roughly (same camera, colour map and
opacity semantics: mean difference below 8/255), and the float image is there.
"""
import os
import subprocess

import numpy as np

import hov_pv_testing as hpt

EXAMPLES = os.path.join(hpt.HERE, os.pardir, "Examples")


def run(args, command, timeout=600):
    proc = subprocess.run(command, env=hpt.pv_env(args), capture_output=True, text=True,
                          timeout=timeout)
    if proc.returncode != 0:
        print(proc.stdout + proc.stderr)
    return proc.returncode, proc.stdout + proc.stderr


def main():
    args = hpt.parse_args()
    failures = []
    plugin_dir = os.path.dirname(args.plugin)
    out1 = os.path.join(args.temp, "paraview_example")
    rc, text = run(args, [args.pvbatch, os.path.join(EXAMPLES, "accurate_volume.py"),
                          "--plugin-dir", plugin_dir, "--out", out1, "--size", "240", "180"])
    hpt.check(failures, rc == 0 and "Accurate Volume (CPU accurate): 56071 cells" in text,
              "accurate_volume.py ran (%s)" % text.strip().splitlines()[-2:])
    ours = hpt.read_png_rgb(os.path.join(out1, "accurate_volume.png"))
    theirs = hpt.read_png_rgb(os.path.join(out1, "paraview_volume.png"))
    background = np.array([0.08, 0.08, 0.12]) * 255
    covered = int((np.abs(ours - background).max(axis=2) > 8).sum())
    mean = float(np.abs(ours - theirs).mean())
    hpt.check(failures, covered > 2000 and mean < 8.0,
              "our screenshot covers %d pixels; mean difference to ParaView's Volume %.2f/255"
              % (covered, mean))
    hpt.check(failures, os.path.exists(os.path.join(out1, "accurate_volume.vti")) and
              os.path.exists(os.path.join(out1, "side_by_side.png")), "float image and layout written")
    out2 = os.path.join(args.temp, "paraview_example_mpi")
    mpi = [args.mpiexec, "-np", "2", "-x", "PYTHONPATH", "-x", "DISPLAY"]
    if os.geteuid() == 0:
        mpi.append("--allow-run-as-root")
    rc, text = run(args, mpi + [args.pvbatch, os.path.join(EXAMPLES, "mpi_accurate_volume.py"),
                                "--plugin-dir", plugin_dir, "--out", out2, "--size", "240", "180"])
    hpt.check(failures, rc == 0 and "2 ranks; rank 0 rendered" in text,
              "mpi_accurate_volume.py ran on 2 ranks")
    hpt.check(failures, all(os.path.exists(os.path.join(out2, f)) for f in (
        "accurate_volume_2_ranks.png", "accurate_volume.vti", "accurate_volume_rank1.vti")),
        "composited screenshot and both ranks' float layers written")
    hpt.finish(failures)


if __name__ == "__main__":
    main()
