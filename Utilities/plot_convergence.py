#!/usr/bin/python3
"""Plot the convergence data of TestCurvedConvergence (issue 6, acceptance 1).

Usage (VTK's/Debian's Python with matplotlib):
    HOV_CONVERGENCE_CSV=conv.csv build/bin/hovKernelTests --gtest_filter='CurvedConvergence*'
    /usr/bin/python3 Utilities/plot_convergence.py conv.csv [out.png]

One panel per table ("breakpoints": PS segments, "smooth": S segments): max
pixel (RGBA) error over a 16x16 ray grid vs mean samples per ray, log-log, for
each quadrature option, with the observed order (least-squares slope over the
last four points) in the legend, ideal first/second-order guides and the
pixel-exact threshold 1e-3 (ElVis Figs. 2, 3, 5, 6). The adaptive mode's
(tolerance, max error) pairs are listed in the panel title.
"""
import csv
import math
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def order(xs, ys, k=4):
    """Minus the least-squares slope of log(y) vs log(x) over the last k points."""
    xs, ys = [math.log(x) for x in xs[-k:]], [math.log(y) for y in ys[-k:]]
    n = len(xs)
    sx, sy = sum(xs), sum(ys)
    sxx = sum(x * x for x in xs)
    sxy = sum(x * y for x, y in zip(xs, ys))
    return -(n * sxy - sx * sy) / (n * sxx - sx * sx)


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    out = sys.argv[2] if len(sys.argv) > 2 else "convergence.png"
    series = defaultdict(lambda: ([], []))
    adaptive = defaultdict(list)
    with open(sys.argv[1]) as f:
        for row in csv.DictReader(f):
            err = max(float(row["max_error"]), 1e-17)
            if row["method"] == "ours_adaptive":
                adaptive[row["case"]].append((float(row["tolerance"]), err))
                continue
            xs, ys = series[(row["case"], row["method"])]
            xs.append(float(row["samples_per_ray"]))
            ys.append(err)
    cases = sorted({c for c, _ in series})
    fig, axes = plt.subplots(1, len(cases), figsize=(6.5 * len(cases), 5), squeeze=False)
    for ax, case in zip(axes[0], cases):
        xmin, xmax = 1e9, 0
        for (c, method), (xs, ys) in sorted(series.items()):
            if c != case:
                continue
            label = method
            if not method.startswith("ours"):
                label += " (order %.2f)" % order(xs, ys)
            else:
                label += " (spectral)"
            ax.loglog(xs, ys, "o-", label=label)
            xmin, xmax = min(xmin, xs[0]), max(xmax, xs[-1])
        # Ideal orders through the first Riemann / ElVis point.
        for (c, method), (xs, ys) in series.items():
            if c == case and method == "riemann":
                ax.loglog([xmin, xmax], [ys[0], ys[0] * xmin / xmax], "k:", lw=0.8,
                          label="first order")
            if c == case and method.startswith("elvis"):
                ax.loglog([xmin, xmax], [ys[0], ys[0] * (xmin / xmax) ** 2], "k--", lw=0.8,
                          label="second order")
        ax.axhline(1e-3, color="r", lw=0.8, label="pixel-exact (1e-3)")
        title = "%s table" % case
        if adaptive[case]:
            title += "\nours adaptive: " + ", ".join(
                "tol %.0e -> %.1e" % te for te in sorted(adaptive[case], reverse=True))
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("samples per ray (mean)")
        ax.set_ylabel("max pixel error (RGBA)")
        ax.set_ylim(1e-17, 1)
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("ElVis verification: cubic Lagrange hexahedron, f = x^2 + y^2 + z^2")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print("wrote", out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
