"""hov.ParaView.Modes: the bracket, the zoo and the order-4 plate in each render mode
through ParaView's "Accurate Volume" (pvbatch, one rank), each compared with the VTK 9.1
module's own float image of the same camera and property (this process).

Two more render the bracket's maximum (CPU) and average (ray cast) intensity through the
AccurateBlendMode property. Two render the bracket (CPU) with no opacity over the lowest 30% of
its range, SkipTransparentCells on and off: the same image, and the transparent cells (the
TransparentCells information property) counted as the standalone mapper counts them. Another renders the bracket with ParaView's default colour map (Cool to Warm: Diverging,
discretized to 256 steps); its standalone reference uses the same map continuous, linearised
to 1e-4 (what the plugin does with it).

Checks per case: the 8-bit screenshot is within 2/255 of the standalone float image (over
black, per channel, every pixel); the plugin's float image (.vti) within 1e-4 of it (2e-3 for
the OpenGL projection: two OpenGL contexts); the native cells reached the mapper (the zoo:
68,714 cells of 4 types); what the standalone mapper rejects (the plate's Lagrange cells in
the CPU and projection modes) gives the same message in ParaView's output and an empty
image in both.
"""
import os

import numpy as np

import hov_pv_testing as hpt

SIZE = (150, 150)


def main():
    args = hpt.parse_args()
    failures = []
    cases = [hpt.make_case(args, name, mode) for name in ("bracket", "zoo", "plate")
             for mode in (0, 1, 2)]
    # ParaView's default colour map (Cool to Warm: Diverging, 256 steps): the volume must use
    # the continuous map linearised to 1e-4, as the standalone mapper does with that setting.
    cases.append(hpt.make_case(args, "bracket", 0, tag="bracket_cpu_default_colormap",
                               paraview_colormap=True))
    # The blend modes through the representation's AccurateBlendMode property.
    for mode, blend in ((0, "Maximum intensity"), (2, "Average intensity")):
        cases.append(hpt.make_case(args, "bracket", mode, tag="bracket_%d_%s" % (
            mode, blend.split()[0].lower()), properties={"AccurateBlendMode": blend}))
    # SkipTransparentCells through the representation: no opacity over the lowest 30% of
    # the range, the skip on (the default) and off; the same image, the transparent cells
    # counted only with it on (TransparentCells, against the standalone mapper's count).
    # The bracket's representation is shared by its cases: the blend mode is set back.
    for skip in (1, 0):
        case = hpt.make_case(args, "bracket", 0, tag="bracket_0_skip_%d" % skip,
                             properties={"SkipTransparentCells": skip,
                                         "AccurateBlendMode": "Composite"})
        lo, hi = case["opacity"][0][0], case["opacity"][-1][0]
        cut = lo + 0.3 * (hi - lo)
        case["opacity"] = [[lo, 0.0], [cut, 0.0]] + [n for n in case["opacity"] if n[0] > cut]
        cases.append(case)
    out = os.path.join(args.temp, "paraview_modes")
    results, stderr = hpt.run_pvbatch(args, cases, out, SIZE)
    messages = hpt.messages_by_case(stderr)
    hpt.check(failures, "Traceback" not in stderr and "Segmentation" not in stderr,
              "pvbatch ran without Python errors or crashes (%.1f s)" % results["seconds"])
    catcher = hpt.MessageCatcher()
    rows = []
    for case, res in zip(cases, results["cases"]):
        name = case["name"]
        if "colormap" in res:
            case["colormap"] = res["colormap"]
            hpt.check(failures, res["colormap"]["discretize"] == 1 and
                      "Diverging" in res["colormap"]["space"],
                      "%s: ParaView's map is %s with Discretize %d" % (
                          name, res["colormap"]["space"], res["colormap"]["discretize"]))
        ref, ref_info, ref_msg = hpt.standalone_render(case, res["camera"], SIZE, catcher)
        png = hpt.read_png_rgb(res["png"])
        pv_float = hpt.read_vti_rgba(res["vti"])
        diff8 = float(np.abs(png - hpt.to_8bit(ref)).max())
        diff_float = float(np.abs(pv_float - ref).max())
        covered = int((ref[..., 3] > 1e-3).sum())
        info = res["info"]
        rows.append((name, covered, diff8, diff_float, info, ref_info))
        hpt.check(failures, diff8 <= 2.0,
                  "%s: screenshot vs standalone float image: max %.0f/255 (<= 2)" % (name, diff8))
        float_tol = 2e-3 if case["mode"] == 1 else 1e-4
        hpt.check(failures, diff_float <= float_tol,
                  "%s: plugin float image vs standalone: max %.2e (<= %.0e)" % (
                      name, diff_float, float_tol))
        ds = hpt.DATASETS[case["dataset"]]
        hpt.check(failures, info["PieceCells"] == ds["cells"] and
                  info["PieceCellTypes"] == ds["types"],
                  "%s: mapper input %d cells of %d types (native: %d of %d)" % (
                      name, info["PieceCells"], info["PieceCellTypes"], ds["cells"], ds["types"]))
        hpt.check(failures, info["RenderedCells"] == ref_info["RenderedCells"] and
                  info["SkippedCells"] == ref_info["SkippedCells"],
                  "%s: rendered/skipped cells %d/%d, standalone %d/%d" % (
                      name, info["RenderedCells"], info["SkippedCells"],
                      ref_info["RenderedCells"], ref_info["SkippedCells"]))
        skip = case["properties"].get("SkipTransparentCells")
        hpt.check(failures, info["TransparentCells"] == ref_info["TransparentCells"] and
                  (skip is None or (info["TransparentCells"] > 0) == (skip == 1)),
                  "%s: transparent cells %d, standalone %d" % (
                      name, info["TransparentCells"], ref_info["TransparentCells"]))
        # One representation (and mapper) per dataset in the view: a message the mapper
        # prints once per input appears under the dataset's first case.
        pv_lines = [line for c in cases if c["dataset"] == case["dataset"]
                    for line in hpt.warning_lines(messages.get(c["name"], ""))]
        ref_lines = hpt.warning_lines(ref_msg)
        hpt.check(failures, all(any(r in p for p in pv_lines) for r in ref_lines),
                  "%s: the standalone mapper's messages %s appear in ParaView's output" % (
                      name, ref_lines))
        if case["dataset"] == "plate" and case["mode"] != 2:
            hpt.check(failures, ref_lines != [] and covered == 0 and png.max() == 0,
                      "%s: Lagrange cells rejected with a message, empty image" % name)
        else:
            hpt.check(failures, covered > 1000, "%s: %d covered pixels" % (name, covered))
        if case["mode"] == 2:
            hpt.check(failures, 0.0 <= info["RayCastErrorEstimate"] <= 1e-3 + 1e-12,
                      "%s: ray-cast error estimate %.2g (<= tolerance 1e-3)" % (
                          name, info["RayCastErrorEstimate"]))
    print("\n| case | covered px | screenshot max diff (x/255) | float max diff | mapper cells "
          "(types) | plugin image s | standalone image s |")
    print("|---|---|---|---|---|---|---|")
    for name, covered, d8, df, info, ref_info in rows:
        print("| %s | %d | %.0f | %.2e | %d (%d) | %.3f | %.3f |" % (
            name, covered, d8, df, info["PieceCells"], info["PieceCellTypes"],
            info["LastImageTime"], ref_info["LastImageTime"]))
    hpt.finish(failures)


if __name__ == "__main__":
    main()
