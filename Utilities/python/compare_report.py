"""Outputs of highordervolume.compare: the CSV and Markdown tables and the montage.

Table columns (CSV names; the Markdown table shows the same numbers, errors with 6 decimals):
key, method, semantics, input, prep_s (resample / tessellation seconds, shared by the rows
that use the same input), first_render_s (first render: includes building sorting and setup
structures), frame_s (median of the timed renders), rss_delta_mib (resident-set growth of
the process over the row, preparation included the first time it is made), data_mib (the
rendered dataset's vtkDataObject::GetActualMemorySize), reference (key of the image compared
with), max_r/g/b, mean_r/g/b, p99_r/g/b (|image - reference| per channel over all pixels,
float, [0,1]), image (the .npy compared), status.
"""
import csv
import os

import numpy as np

CSV_FIELDS = (["key", "method", "semantics", "input", "prep_s", "first_render_s", "frame_s",
               "rss_delta_mib", "data_mib", "reference"]
              + ["%s_%s" % (stat, c) for stat in ("max", "mean", "p99") for c in "rgb"]
              + ["image", "status"])
MD_HEADER = ["key", "method", "semantics", "input", "prep [s]", "first render [s]",
             "frame [s]", "RSS delta [MiB]", "data [MiB]", "max err R/G/B", "mean err R/G/B",
             "p99 err R/G/B", "status"]


def write_csv(rows, path):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=CSV_FIELDS, extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow({k: row.get(k, "") for k in CSV_FIELDS})


def _triple(row, stat):
    if row.get("max_r", "") == "":
        return "-"
    return "/".join("%.6f" % row["%s_%s" % (stat, c)] for c in "rgb")


def markdown_lines(rows):
    lines = ["| " + " | ".join(MD_HEADER) + " |", "|" + "---|" * len(MD_HEADER)]
    for r in rows:
        cells = [r["key"], r["method"], r["semantics"], r.get("input", "-"),
                 "%.3f" % r["prep_s"] if "prep_s" in r else "-",
                 "%.3f" % r["first_render_s"] if "first_render_s" in r else "-",
                 "%.3f" % r["frame_s"] if "frame_s" in r else "-",
                 "%.1f" % r["rss_delta_mib"] if "rss_delta_mib" in r else "-",
                 "%.1f" % r["data_mib"] if "data_mib" in r else "-",
                 _triple(r, "max"), _triple(r, "mean"), _triple(r, "p99"), r["status"]]
        lines.append("| " + " | ".join(str(c).replace("|", "/") for c in cells) + " |")
    return lines


def write_markdown(rows, path, title, notes):
    text = "\n".join(["# " + title, ""] + notes + [""] + markdown_lines(rows)) + "\n"
    with open(path, "w") as f:
        f.write(text)
    return text


def parse_markdown_table(text):
    """Rows of the first Markdown table in text as dicts keyed by the header (for tests)."""
    lines = [ln.strip() for ln in text.splitlines() if ln.strip().startswith("|")]
    header = [c.strip() for c in lines[0].strip("|").split("|")]
    rows = []
    for ln in lines[2:]:
        cells = [c.strip() for c in ln.strip("|").split("|")]
        rows.append(dict(zip(header, cells)))
    return rows


def write_montage(entries, path, diff_scale, columns=3, panel_inches=1.6, dpi=100,
                  colors=None):
    """entries: (label, image float RGB (h, w, 3) or None, reference or None, max error).
    Each method: its image and |image - reference| (max over channels) in false colour,
    one shared colour bar from 0 to diff_scale. colors: quantise the PNG to that many
    colours (smaller files), None for full colour."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = (len(entries) + columns - 1) // columns
    height = rows * (panel_inches + 0.3) + 0.6  # 0.6 inch at the bottom for the colour bar
    fig, axes = plt.subplots(rows, 2 * columns, squeeze=False,
                             figsize=(2 * columns * panel_inches, height))
    fig.patch.set_facecolor("black")
    mappable = None
    for i in range(rows * columns):
        ax_img, ax_diff = axes[i // columns][2 * (i % columns)], axes[i // columns][2 * (i % columns) + 1]
        for ax in (ax_img, ax_diff):
            ax.set_axis_off()
        if i >= len(entries):
            continue
        label, image, reference, max_err = entries[i]
        if image is None:
            ax_img.set_title(label + "\n(failed)", color="white", fontsize=7)
            continue
        ax_img.imshow(np.clip(image, 0, 1), origin="lower", interpolation="nearest")
        ax_img.set_title(label, color="white", fontsize=8)
        if reference is not None:
            diff = np.abs(image.astype(np.float64) - reference).max(axis=2)
            mappable = ax_diff.imshow(diff, origin="lower", cmap="inferno", vmin=0.0,
                                      vmax=diff_scale, interpolation="nearest")
            ax_diff.set_title("max err %.3g" % max_err, color="white", fontsize=7)
    if mappable is not None:
        cax = fig.add_axes([0.25, 0.42 / height, 0.5, 0.08 / height])
        bar = fig.colorbar(mappable, cax=cax, orientation="horizontal")
        bar.set_label("|image - reference|, max over R/G/B (clipped at %.3g)" % diff_scale,
                      color="white", fontsize=7)
        bar.ax.tick_params(colors="white", labelsize=6)
    fig.subplots_adjust(left=0.005, right=0.995, top=1.0 - 0.25 / height,
                        bottom=0.6 / height, wspace=0.03, hspace=0.3 / panel_inches)
    fig.savefig(path, dpi=dpi, facecolor="black")
    plt.close(fig)
    if colors:
        from PIL import Image
        Image.open(path).convert("RGB").quantize(colors).save(path, optimize=True)
