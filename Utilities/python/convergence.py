"""Convergence study: max pixel error against cost for one knob of one rendering route.

    hov-convergence DATA.vtu ARRAY --study STUDY [--values V1,V2,...] [--out DIR] [--cost time|samples]
    /usr/bin/python3 -m highordervolume.convergence ...   (the same)

Studies (knob, reference, cost in samples):
  resample            vtkResampleToImage points on the longest side + vtkGPUVolumeRayCastMapper
                      (sample distance --gpu-sample-factor x voxel spacing); reference: our
                      CPU_ACCURATE image (RAY_CAST for Lagrange cells), GPU-compatible
                      semantics; samples = voxels
  gpu-sample          GPU sample distance as a fraction of the voxel spacing of a
                      --resolution resample; samples = 1 / fraction
  ugrc-sample         vtkUnstructuredGridVolumeRayCastMapper ImageSampleDistance (pixels
                      between rays); VTK-unstructured semantics; samples = rays cast
  projection          our OPENGL_PROJECTION ProjectionColorMethod M0..M3 (values 0..3);
                      VTK-unstructured semantics; samples = method index + 1
  raycast-tolerance   our RAY_CAST RayCastTolerance (only if the mapper has RAY_CAST);
                      VTK-unstructured semantics; samples = 1 / tolerance

The error of a run is max over pixels and R/G/B of |image - reference| (RGB over black in
[0,1]; also mean and p99). The observed order is the least-squares slope of
log(max error) against log(cost) (runs with zero error are left out; NaN if fewer than two
remain). Writes <out>/convergence_<study>.csv (one row per value, the fitted orders repeated
on every row) and <out>/convergence_<study>.png (log-log plot with the fitted line).
"""
import argparse
import csv
import math
import os
import sys

import numpy as np
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow

from . import compare as cmp
from . import render_tools as rt
from .offscreen import OffscreenError

STUDIES = {
    # name: (semantics, default values, knob label)
    "resample": ("gpu", "32,64,128", "vtkResampleToImage points on the longest side"),
    "gpu-sample": ("gpu", "1,0.5,0.25", "GPU sample distance / voxel spacing"),
    "ugrc-sample": ("vtk", "4,2,1", "vtkUnstructuredGridVolumeRayCastMapper ImageSampleDistance"),
    "projection": ("vtk", "0,1,2,3", "OPENGL_PROJECTION ProjectionColorMethod"),
    "raycast-tolerance": ("vtk", "1e-2,1e-3,1e-4", "RAY_CAST RayCastTolerance"),
}
CSV_FIELDS = ["study", "knob", "value", "cost_time_s", "cost_samples", "max_err", "mean_err",
              "p99_err", "order_time", "order_samples", "image", "status"]


def study_spec(study, value, args, width, height):
    """(spec for compare.run_one, cost in samples) of one value of the knob."""
    sem = STUDIES[study][0]
    if study == "resample":
        n = int(value)
        return ({"key": "gpu_%d" % n, "input": "resample", "resolution": n, "semantics": sem,
                 "name": "resample %d + GPU" % n, "make": cmp.gpu_mapper}, None)
    if study == "gpu-sample":
        return ({"key": "gpu_sample_%g" % value, "input": "resample",
                 "resolution": args.resolution, "sample_factor": value, "semantics": sem,
                 "name": "GPU sample %g" % value, "make": cmp.gpu_mapper}, 1.0 / value)
    if study == "ugrc-sample":
        return ({"key": "ugrc_%g" % value, "input": "tets", "semantics": sem,
                 "name": "UG ray cast ISD %g" % value,
                 "make": lambda v=value: cmp.ug_raycast(v)}, width * height / value ** 2)
    if study == "projection":
        k = int(value)
        return ({"key": "proj_m%d" % k, "input": "native", "semantics": sem,
                 "name": "projection M%d" % k,
                 "make": lambda k=k: cmp.hov_mapper(sem, "proj", k)}, k + 1.0)
    if study == "raycast-tolerance":
        if not cmp.has_ray_cast() or not hasattr(cmp.vtkHighOrderVolumeMapper,
                                                 "SetRayCastTolerance"):
            raise ValueError("this vtkHighOrderVolumeMapper has no RAY_CAST render mode "
                             "with SetRayCastTolerance")
        return ({"key": "ray_%g" % value, "input": "native", "semantics": sem,
                 "name": "ray cast tol %g" % value,
                 "make": lambda v=value: cmp.hov_mapper(sem, "ray", v)}, 1.0 / value)
    raise ValueError("unknown study %s" % study)


def fitted_order(costs, errors):
    """Least-squares slope of log(error) against log(cost) over the positive pairs."""
    pairs = [(c, e) for c, e in zip(costs, errors) if c > 0 and e > 0
             and math.isfinite(c) and math.isfinite(e)]
    if len(pairs) < 2 or len({c for c, _ in pairs}) < 2:
        return float("nan")
    x, y = np.log([c for c, _ in pairs]), np.log([e for _, e in pairs])
    return float(np.polyfit(x, y, 1)[0])


def run_study(args):
    scene = cmp.Scene(args)
    sem = STUDIES[args.study][0]
    values = [float(v) for v in (args.values or STUDIES[args.study][1]).split(",") if v.strip()]
    if not values or min(values) <= 0.0 and args.study != "projection":
        raise ValueError("--values: positive numbers needed")
    specs = [study_spec(args.study, v, args, scene.width, scene.height) for v in values]
    log = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(log)
    log.seen = 0
    catcher = rt.ErrorCatcher()
    progress = cmp.Progress(len(values) + 1)
    rt.warm_up_gl()
    os.makedirs(args.out, exist_ok=True)
    ref_spec = dict(cmp.reference_spec(sem, scene.ray_reference), key="reference_" + sem)
    progress.start(ref_spec["key"])
    ref_row, _, reference = cmp.run_one(scene, ref_spec, args.frames, catcher, log, progress)
    progress.finish(ref_row["status"])
    if reference is None:
        raise ValueError("the reference image failed: %s" % ref_row["status"])
    np.save(os.path.join(args.out, "convergence_%s_reference.npy" % args.study), reference)
    rows = []
    for value, (spec, samples) in zip(values, specs):
        progress.start(spec["key"])
        row = {"study": args.study, "knob": STUDIES[args.study][2], "value": value}
        try:
            res_row, _, image = cmp.run_one(scene, spec, args.frames, catcher, log, progress)
            row["status"] = res_row["status"]
        except Exception as exc:  # report and go on
            image, res_row = None, {}
            row["status"] = "failed: %r" % exc
        if spec["input"] == "resample" and samples is None:
            samples = float(np.prod(rt.resample_dims(scene.grid.GetBounds(), int(value))))
        row["cost_samples"] = samples
        if image is not None:
            row["image"] = "convergence_%s_%s.npy" % (args.study, spec["key"])
            np.save(os.path.join(args.out, row["image"]), image)
            stats = rt.error_stats(image, reference)
            row.update({"cost_time_s": res_row["frame_s"], "max_err": max(stats["max"]),
                        "mean_err": float(np.mean(stats["mean"])),
                        "p99_err": max(stats["p99"])})
        progress.finish(row["status"])
        rows.append(row)
    ok = [r for r in rows if "max_err" in r]
    order_time = fitted_order([r["cost_time_s"] for r in ok], [r["max_err"] for r in ok])
    order_samples = fitted_order([r["cost_samples"] for r in ok], [r["max_err"] for r in ok])
    for r in rows:
        r["order_time"], r["order_samples"] = order_time, order_samples
    return rows, order_time, order_samples


def write_csv(rows, path):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=CSV_FIELDS, extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow({k: row.get(k, "") for k in CSV_FIELDS})


def plot(rows, cost, order, path, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ok = [r for r in rows if r.get("max_err", 0) > 0]
    key = "cost_time_s" if cost == "time" else "cost_samples"
    fig, ax = plt.subplots(figsize=(5.5, 4.0))
    x = np.array([r[key] for r in ok], dtype=float)
    y = np.array([r["max_err"] for r in ok], dtype=float)
    ax.loglog(x, y, "o-", label="max pixel error")
    ax.loglog(x, [r["p99_err"] for r in ok], "s--", alpha=0.6, label="p99 pixel error")
    for r in ok:
        ax.annotate("%g" % r["value"], (r[key], r["max_err"]), textcoords="offset points",
                    xytext=(4, 4), fontsize=8)
    if len(ok) >= 2 and math.isfinite(order):
        c = np.polyfit(np.log(x), np.log(y), 1)
        xs = np.array([x.min(), x.max()])
        ax.loglog(xs, np.exp(c[1]) * xs ** c[0], "k:", label="fit: slope %.2f" % order)
    ax.set_xlabel("frame time [s]" if cost == "time" else "samples")
    ax.set_ylabel("error vs our accurate image")
    ax.set_title(title, fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def parse_args(argv=None):
    parser = argparse.ArgumentParser(
        prog="hov-convergence", description="Max pixel error against cost for one knob, "
        "with the observed order (log-log slope); PNG plot + CSV.")
    cmp.add_scene_arguments(parser)
    parser.add_argument("--study", default="resample", choices=sorted(STUDIES))
    parser.add_argument("--values", help="comma-separated knob values (default per study)")
    parser.add_argument("--resolution", type=int, default=64,
                        help="resample resolution of the gpu-sample study")
    parser.add_argument("--cost", choices=("time", "samples"), default="samples",
                        help="x axis of the plot")
    parser.add_argument("--out", default="hov_convergence_out", help="output directory")
    return parser.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    try:
        rows, order_time, order_samples = run_study(args)
    except (ValueError, OSError, OffscreenError) as exc:  # bad file, array, TF, no window ...
        print("hov-convergence: %s" % exc, file=sys.stderr)
        return 1
    base = os.path.join(args.out, "convergence_%s" % args.study)
    write_csv(rows, base + ".csv")
    order = order_time if args.cost == "time" else order_samples
    plot(rows, args.cost, order, base + ".png",
         "%s: %s, '%s'" % (args.study, os.path.basename(args.data), args.array))
    for r in rows:
        print("%-10g time %-8s samples %-10s max %-10s %s" % (
            r["value"], "%.4f" % r["cost_time_s"] if "cost_time_s" in r else "-",
            "%.4g" % r["cost_samples"], "%.6f" % r["max_err"] if "max_err" in r else "-",
            r["status"]))
    print("observed order: %.3f vs time, %.3f vs samples" % (order_time, order_samples))
    return 0 if any("max_err" in r for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
