"""Our pixel-exact image against the usual route: resample to a grid + vtkGPUVolumeRayCastMapper.

    hov-resample-study DATA.vtu ARRAY [--resolutions 64,128,256] [--size W H] [--out DIR]
                       [--tolerance 1e-3] [--tf TF.json] [--azimuth A --elevation E --zoom Z]
    /usr/bin/python3 -m highordervolume.resample_study ...   (the same)

The ElVis comparison (Nelson et al. 2012, Figs. 7 and 9-11) for any dataset the module reads,
curved Lagrange cells included. Under one camera and one vtkVolumeProperty in GPU-compatible
opacity semantics (the limit vtkGPUVolumeRayCastMapper converges to):

  ours          vtkHighOrderVolumeMapper RAY_CAST at --tolerance (default 1e-3 per channel,
                "pixel-exact"): the reference image; its end-to-end time is the first render
                (reading the cells, building the BVH, tracing every pixel) and its error is the
                mapper's own estimate (the largest value of GetRayCastErrorImage()).
  resample_<n>  vtkResampleToImage with n points on the longest side (cubic voxels) +
                vtkGPUVolumeRayCastMapper (sample distance --gpu-sample-factor x the voxel
                spacing; points outside the mesh get opacity 0); end-to-end = resample time +
                first render.

Prints and writes (--out): resample_study.md and .csv (per route: resample time, first render,
steady frame, end-to-end time, memory of the resampled image and the process's growth, max /
mean / p99 error per pixel (max over R/G/B) against our image, and whether it is visible, i.e.
above 1/255), resample_study_<route>.png/.npy (the images), resample_study_montage.png (every
image beside its false-colour difference map) and resample_study.png (error against end-to-end
time, log-log, and error against resolution).
"""
import argparse
import csv
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow

from . import compare as cmp
from . import compare_report as report
from . import render_tools as rt
from .offscreen import OffscreenError

VISIBLE = 1.0 / 255.0
FIELDS = ["route", "resolution", "dims", "resample_s", "first_render_s", "frame_s",
          "end_to_end_s", "data_mib", "rss_delta_mib", "max_err", "mean_err", "p99_err",
          "visible", "image", "status"]


def parse_args(argv=None):
    parser = argparse.ArgumentParser(
        prog="hov-resample-study",
        description="Our RAY_CAST pixel-exact image against vtkResampleToImage + "
        "vtkGPUVolumeRayCastMapper at several resolutions: time, memory, error, images, plot.")
    cmp.add_scene_arguments(parser)
    parser.add_argument("--resolutions", default="64,128,256",
                        help="vtkResampleToImage points on the longest side, comma separated")
    parser.add_argument("--tolerance", type=float, default=1e-3,
                        help="our RAY_CAST tolerance per channel (default 1e-3)")
    parser.add_argument("--out", default="hov_resample_study_out", help="output directory")
    parser.add_argument("--diff-scale", type=float, default=0.1,
                        help="error at full saturation of the montage's difference maps")
    args = parser.parse_args(argv)
    args.resolutions = [int(r) for r in args.resolutions.split(",") if r.strip()]
    if not args.resolutions or min(args.resolutions) < 2:
        parser.error("--resolutions: integers >= 2 needed")
    if not 1e-12 <= args.tolerance <= 0.1:
        parser.error("--tolerance: in [1e-12, 0.1]")
    if args.frames < 1 or min(args.size) < 8:
        parser.error("--frames >= 1 and --size >= 8 needed")
    args.semantics = ["gpu"]
    return args


def error_image_max(image):
    """Largest value of the mapper's per-pixel error estimate (array "Error")."""
    array = image.GetPointData().GetArray("Error") if image is not None else None
    if array is None or array.GetNumberOfTuples() == 0:
        return float("nan")
    return float(vtk_to_numpy(array).max())


def pixel_errors(image, reference):
    """max / mean / p99 over pixels of the largest |difference| of R, G, B."""
    d = np.abs(image.astype(np.float64) - reference.astype(np.float64)).max(axis=2)
    return float(d.max()), float(d.mean()), float(np.percentile(d, 99.0))


def run(args):
    if not cmp.has_ray_cast():
        raise ValueError("this vtkHighOrderVolumeMapper has no RAY_CAST render mode")
    scene = cmp.Scene(args)
    log = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(log)
    log.seen = 0
    catcher = rt.ErrorCatcher()
    progress = cmp.Progress(1 + len(args.resolutions))
    rt.warm_up_gl()
    os.makedirs(args.out, exist_ok=True)
    kept = []

    def ours():
        m = cmp.hov_mapper("gpu", "ray", args.tolerance)
        kept.append(m)  # run_one drops its reference; the error image is read afterwards
        return m

    spec = {"key": "ours", "input": "native", "semantics": "gpu",
            "name": "ours RAY_CAST tol %g" % args.tolerance, "make": ours}
    progress.start("ours")
    row, res, reference = cmp.run_one(scene, spec, args.frames, catcher, log, progress)
    progress.finish(row["status"])
    if reference is None:
        raise ValueError("our RAY_CAST image failed: %s" % row["status"])
    estimate = error_image_max(kept[0].GetRayCastErrorImage())
    rows = [{"route": "ours RAY_CAST tol %g" % args.tolerance, "resolution": "-",
             "dims": "native cells (%d)" % scene.grid.GetNumberOfCells(), "resample_s": 0.0,
             "first_render_s": row["first_render_s"], "frame_s": row["frame_s"],
             "end_to_end_s": row["first_render_s"], "data_mib": row["data_mib"],
             "rss_delta_mib": row["rss_delta_mib"], "max_err": estimate,
             "mean_err": float("nan"), "p99_err": float("nan"),
             "visible": "no" if estimate < VISIBLE else "yes",
             "image": "resample_study_ours.npy", "status": row["status"] + " (error: estimate)"}]
    rt.write_png(res["png"], os.path.join(args.out, "resample_study_ours.png"))
    np.save(os.path.join(args.out, "resample_study_ours.npy"), reference)
    entries = [("ours RAY_CAST", reference, reference, 0.0)]
    for n in args.resolutions:
        key = "resample_%d" % n
        spec = {"key": key, "input": "resample", "resolution": n, "semantics": "gpu",
                "name": "vtkResampleToImage %d + vtkGPUVolumeRayCastMapper" % n,
                "make": cmp.gpu_mapper}
        progress.start(key)
        try:
            r, res, image = cmp.run_one(scene, spec, args.frames, catcher, log, progress)
        except Exception as exc:  # report and go on
            r, res, image = {"status": "failed: %r" % exc}, None, None
        out = {"route": spec["name"], "resolution": n, "status": r["status"],
               "dims": "x".join(map(str, rt.resample_dims(scene.grid.GetBounds(), n)))}
        if image is not None:
            out.update({"resample_s": r["prep_s"], "first_render_s": r["first_render_s"],
                        "frame_s": r["frame_s"], "end_to_end_s": r["prep_s"] + r["first_render_s"],
                        "data_mib": r["data_mib"], "rss_delta_mib": r["rss_delta_mib"],
                        "image": "resample_study_%s.npy" % key})
            out["max_err"], out["mean_err"], out["p99_err"] = pixel_errors(image, reference)
            out["visible"] = "yes" if out["max_err"] > VISIBLE else "no"
            np.save(os.path.join(args.out, out["image"]), image)
            rt.write_png(res["png"], os.path.join(args.out, "resample_study_%s.png" % key))
            entries.append((key, image, reference, out["max_err"]))
        progress.finish(out["status"])
        rows.append(out)
        scene.cache.clear()  # the resampled images are large: one at a time
    return rows, entries, scene


def fmt(v, spec="%.3f"):
    if isinstance(v, float) and not np.isfinite(v):
        return "-"
    return spec % v if isinstance(v, (int, float)) else str(v)


def write_tables(rows, args, scene, path_md, path_csv):
    with open(path_csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS, extrasaction="ignore")
        writer.writeheader()
        for r in rows:
            writer.writerow({k: r.get(k, "") for k in FIELDS})
    head = ["route", "grid", "resample [s]", "first render [s]", "frame [s]", "end-to-end [s]",
            "image [MiB]", "RSS growth [MiB]", "max err", "mean err", "p99 err",
            "visible (> 1/255)"]
    lines = ["# hov-resample-study: %s, '%s'" % (os.path.basename(args.data), args.array), "",
             "%dx%d pixels, GPU-compatible opacity semantics, reference: our RAY_CAST image "
             "(tolerance %g per channel; its own row gives its estimated error). Errors: per "
             "pixel, the largest |difference| of R, G, B over black, in [0, 1]. End-to-end: "
             "resampling + first render (ours: first render, structures included)."
             % (scene.width, scene.height, args.tolerance), "",
             "| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in rows:
        cells = [r["route"], r["dims"], fmt(r.get("resample_s", "-")),
                 fmt(r.get("first_render_s", "-")), fmt(r.get("frame_s", "-")),
                 fmt(r.get("end_to_end_s", "-")), fmt(r.get("data_mib", "-"), "%.1f"),
                 fmt(r.get("rss_delta_mib", "-"), "%.1f"), fmt(r.get("max_err", "-"), "%.2e"),
                 fmt(r.get("mean_err", "-"), "%.2e"), fmt(r.get("p99_err", "-"), "%.2e"),
                 r.get("visible", "-")]
        lines.append("| " + " | ".join(cells) + " |")
    text = "\n".join(lines) + "\n"
    with open(path_md, "w") as f:
        f.write(text)
    return text


def plot(rows, path, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ours, routes = rows[0], [r for r in rows[1:] if "max_err" in r]
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10.0, 4.0))
    if routes:
        t = [r["end_to_end_s"] for r in routes]
        for key, style, label in (("max_err", "o-", "resample + GPU: max error"),
                                  ("mean_err", "s--", "resample + GPU: mean error")):
            y = [max(r[key], 1e-9) for r in routes]
            ax.loglog(t, y, style, label=label)
            bx.loglog([r["resolution"] for r in routes], y, style, label=label)
        for r in routes:
            ax.annotate("%d^3" % r["resolution"], (r["end_to_end_s"], max(r["max_err"], 1e-9)),
                        textcoords="offset points", xytext=(4, 4), fontsize=8)
    est = max(ours["max_err"], 1e-12)
    ax.loglog([ours["end_to_end_s"]], [est], "r*", markersize=14,
              label="ours RAY_CAST (estimated error)")
    for a in (ax, bx):
        a.axhline(VISIBLE, color="gray", lw=0.8, ls=":", label="1/255 (visible)")
        a.grid(True, which="both", alpha=0.3)
        a.set_ylabel("error vs our pixel-exact image")
        a.legend(fontsize=7)
    ax.set_xlabel("end-to-end time [s] (resample + first render)")
    bx.set_xlabel("vtkResampleToImage points on the longest side")
    fig.suptitle(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main(argv=None):
    args = parse_args(argv)
    try:
        rows, entries, scene = run(args)
    except (ValueError, OSError, OffscreenError) as exc:  # ..., no render window
        print("hov-resample-study: %s" % exc, file=sys.stderr)
        return 1
    base = os.path.join(args.out, "resample_study")
    text = write_tables(rows, args, scene, base + ".md", base + ".csv")
    report.write_montage(entries, base + "_montage.png", args.diff_scale,
                         panel_inches=max(1.2, scene.width / 100.0))
    plot(rows, base + ".png", "%s, '%s': our RAY_CAST vs vtkResampleToImage + "
         "vtkGPUVolumeRayCastMapper" % (os.path.basename(args.data), args.array))
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
