"""ParaView plugin benchmarks (not ctest cases): ./Utilities/paraview-benchmark.sh runs this.

A. A >= 2M-tetrahedron mesh (ParaView's Wavelet [-e, e]^3, e = 37 by default, through its
   Tetrahedralize filter: 2,026,120 tetrahedra) at 1024^2 in pvbatch, "Accurate Volume"
   (CPU accurate, VTK-unstructured semantics) beside ParaView's own "Volume" (projected
   tetrahedra) in the same run, frames interleaved, the camera turning 3 degrees per
   frame: 1 rank x 2 threads, 1 rank x 1 thread, 2 ranks x 1 thread. Reports the median
   frame time of each and the ratios.
B. The native zoo (68,714 cells of 4 types) at the same size, camera, property and thread
   count through the plugin (pvbatch) and through the VTK 9.1 module standalone (a separate
   python3 process, a render window), alternating runs; reports the median frame times and
   the ratio plugin / standalone (acceptance: <= 1.3).
C. The same for the order-4 T-junction in the ray-cast mode (one still frame per run at
   --raycast-size, default 160^2), with the cost per ray.

    python3 run_benchmarks.py --plugin <HighOrderVolume.so> --pvpython <dist-packages>
        --data Testing/Data --temp <folder> [--size 1024] [--frames 5] [--extent 37]
        [--parts A,B,C] [--raycast-size 160] [--markdown out.md]
"""
import json
import os
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, os.pardir, "Testing"))
import hov_pv_testing as hpt  # noqa: E402

PV_BENCH = os.path.join(HERE, "pv_bench_frames.py")


def extra(parser):
    parser.add_argument("--size", type=int, default=1024)
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--extent", type=int, default=37)
    parser.add_argument("--rounds", type=int, default=2, help="part B: alternating rounds")
    parser.add_argument("--parts", default="A,B,C")
    parser.add_argument("--raycast-size", type=int, default=160)
    parser.add_argument("--markdown", default=None)


def run_pvbatch(args, spec, ranks, threads, name):
    out = os.path.join(args.temp, "pv_bench_%s.json" % name)
    spec = dict(spec, plugin=args.plugin, out=out)
    spec_path = os.path.join(args.temp, "pv_bench_%s_spec.json" % name)
    with open(spec_path, "w") as f:
        json.dump(spec, f)
    command = [args.pvbatch, PV_BENCH, spec_path]
    if ranks > 1:
        command = [args.mpiexec, "-np", str(ranks), "-x", "PYTHONPATH", "-x", "DISPLAY", "-x",
                   "VTK_SMP_MAX_THREADS"] + (["--allow-run-as-root"] if os.geteuid() == 0 else []) \
            + command
    start = time.perf_counter()
    proc = subprocess.run(command, env=hpt.pv_env(args, threads), capture_output=True, text=True)
    if proc.returncode != 0 or not os.path.exists(out):
        print(proc.stdout + proc.stderr)
        raise RuntimeError("pvbatch benchmark %s failed" % name)
    with open(out) as f:
        result = json.load(f)
    result["wall"] = time.perf_counter() - start
    os.remove(out)
    return result


def part_a(args, lines):
    lo, hi = 37.35, 276.83  # RTData's range on the Wavelet
    color = [[lo + f * (hi - lo), r, g, b] for f, r, g, b in hpt.COLOR_NODES]
    opacity = [[lo + f * (hi - lo), a] for f, a in hpt.OPACITY_NODES]
    spec = {"size": [args.size, args.size], "frames": args.frames, "warmup": 1,
            "source": {"kind": "wavelet", "extent": args.extent},
            "representations": ["Accurate Volume", "Volume"], "mode": "CPU accurate",
            "semantics": "VTK unstructured", "color": color, "opacity": opacity,
            "unit_distance": 4.0, "azimuth_step": 3.0}
    rows = {}
    for name, ranks, threads in (("1x2", 1, 2), ("1x1", 1, 1), ("2x1", 2, 1)):
        res = run_pvbatch(args, spec, ranks, threads, "A_" + name)
        ours = statistics.median(res["times"]["Accurate Volume"])
        pt = statistics.median(res["times"]["Volume"])
        rows[name] = (ours, pt, res)
        print("A %s: %d cells, ours %.3f s (last image on rank 0 %.3f s, %d cells), PT %.3f s "
              "per frame (run %.0f s, load %.1f)" % (
                  name, res["cells"], ours, res["image_time_rank0"], res["piece_cells_rank0"], pt,
                  res["wall"], os.getloadavg()[0]), flush=True)
    cells = rows["1x2"][2]["cells"]
    lines += ["", "A. Wavelet [-%d, %d]^3 tetrahedralised: %s tetrahedra, %dx%d, CPU accurate in "
              "VTK-unstructured semantics beside ParaView's Volume (projected tetrahedra), "
              "median of %d frames (camera +3 degrees per frame), frames interleaved:" % (
                  args.extent, args.extent, format(cells, ","), args.size, args.size, args.frames),
              "",
              "| ranks x threads | Accurate Volume (s) | ParaView Volume, PT (s) | PT / ours | "
              "ours: 1 rank x 1 thread / this |",
              "|---|---|---|---|---|"]
    base = rows["1x1"][0]
    for name in ("1x2", "1x1", "2x1"):
        ours, pt, _ = rows[name]
        lines.append("| %s | %.3f | %.3f | %.2f | %.2f |" % (
            name.replace("x", " x "), ours, pt, pt / ours, base / ours))


def standalone_frames(args, case, size, frames, threads):
    """The VTK 9.1 module's frame times for the same case (render window, same camera steps)."""
    os.environ["VTK_SMP_MAX_THREADS"] = str(threads)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
    from vtkmodules.vtkCommonCore import vtkSMPTools
    from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderWindow,
                                             vtkRenderer, vtkVolume, vtkVolumeProperty)
    from highordervolume import vtkHighOrderVolumeMapper
    vtkSMPTools.Initialize(threads)
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(case["data"])
    reader.Update()
    ctf = vtkColorTransferFunction()
    for x, r, g, b in case["color"]:
        ctf.AddRGBPoint(x, r, g, b)
    pwf = vtkPiecewiseFunction()
    for x, a in case["opacity"]:
        pwf.AddPoint(x, a)
    prop = vtkVolumeProperty()
    prop.SetColor(ctf)
    prop.SetScalarOpacity(pwf)
    prop.SetScalarOpacityUnitDistance(case["unit_distance"])
    prop.SetInterpolationTypeToLinear()
    mapper = vtkHighOrderVolumeMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectScalarArray(case["array"])
    mapper.SetRenderMode(case["mode"])
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    ren = vtkRenderer()
    ren.AddVolume(volume)
    cam = ren.GetActiveCamera()
    c = case["camera"]
    cam.SetPosition(*c["position"])
    cam.SetFocalPoint(*c["focal_point"])
    cam.SetViewUp(*c["view_up"])
    cam.SetViewAngle(c["view_angle"])
    win = vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetSize(size, size)
    win.AddRenderer(ren)
    ren.ResetCameraClippingRange()
    win.Render()  # warm-up: set-up and sort structures
    times = []
    for _ in range(frames):
        cam.Azimuth(3.0)
        ren.ResetCameraClippingRange()
        start = time.perf_counter()
        win.Render()
        times.append(time.perf_counter() - start)
    result = {"times": times, "image": mapper.GetLastImageTime(), "rays": mapper.GetNumberOfRays(),
              "backend": vtkSMPTools.GetBackend(),
              "threads": vtkSMPTools.GetEstimatedNumberOfThreads()}
    win.Finalize()
    return result


SAME_FRAME = {  # part: (dataset, mode, semantics, label)
    "B": ("zoo", 0, "GPU compatible", "native zoo (68,714 cells of 4 types), CPU accurate"),
    "C": ("tjunction_p4", 2, "GPU compatible", "order-4 T-junction (3,790 Lagrange tetrahedra), "
          "ray cast, tolerance 1e-3"),
}


def part_same_frame(args, lines, part):
    """The same frames through the plugin (pvbatch) and standalone, alternating runs."""
    dataset, mode, semantics, label = SAME_FRAME[part]
    case = hpt.make_case(args, dataset, mode)
    size = args.size if part == "B" else args.raycast_size
    frames = args.frames if part == "B" else 1
    threads = 2
    spec = {"size": [size, size], "frames": frames, "warmup": 1,
            "source": {"kind": "file", "path": case["data"], "array": case["array"]},
            "representations": ["Accurate Volume"], "mode": hpt.MODE_NAMES[mode],
            "semantics": semantics, "color": case["color"], "opacity": case["opacity"],
            "unit_distance": case["unit_distance"], "camera": case["camera"], "azimuth_step": 3.0}
    plugin, standalone = [], []
    for round_ in range(args.rounds):
        res = run_pvbatch(args, spec, 1, threads, part)
        plugin.append(statistics.median(res["times"]["Accurate Volume"]))
        proc = subprocess.run([sys.executable, __file__, "--standalone", part] + sys.argv[1:],
                              capture_output=True, text=True,
                              env=dict(os.environ, VTK_SMP_MAX_THREADS=str(threads)))
        out = [line for line in proc.stdout.splitlines() if line.startswith("STANDALONE ")]
        if not out:
            print(proc.stdout + proc.stderr)
            raise RuntimeError("standalone run failed")
        sa = json.loads(out[0][len("STANDALONE "):])
        standalone.append(statistics.median(sa["times"]))
        print("%s round %d: plugin %.3f s (image %.3f s, %d cells of %d types), standalone %.3f s "
              "(image %.3f s, %d rays, %s %d threads), load %.1f" % (
                  part, round_ + 1, plugin[-1], res["image_time_rank0"], res["piece_cells_rank0"],
                  res["cell_types_rank0"], standalone[-1], sa["image"], sa["rays"], sa["backend"],
                  sa["threads"], os.getloadavg()[0]), flush=True)
    p, s = statistics.median(plugin), statistics.median(standalone)
    per_ray = ", %.2f ms per ray (%d rays)" % (1000 * s / sa["rays"], sa["rays"]) if mode == 2 else ""
    lines += ["", "%s. The %s, %dx%d, 2 threads, same camera and property, median of %d frames "
              "per run, %d alternating runs each%s:" % (part, label, size, size, frames,
                                                        args.rounds, per_ray), "",
              "| | plugin (pvbatch) | standalone (VTK 9.1 module) | plugin / standalone |",
              "|---|---|---|---|",
              "| frame (s), per run | %s | %s | %.2f |" % (
                  ", ".join("%.3f" % v for v in plugin),
                  ", ".join("%.3f" % v for v in standalone), p / s)]


def standalone_part(args, part):
    dataset, mode, _, _ = SAME_FRAME[part]
    case = hpt.make_case(args, dataset, mode)
    size = args.size if part == "B" else args.raycast_size
    frames = args.frames if part == "B" else 1
    print("STANDALONE " + json.dumps(standalone_frames(args, case, size, frames, 2)))


def main():
    standalone = None
    if "--standalone" in sys.argv:
        at = sys.argv.index("--standalone")
        standalone = sys.argv[at + 1]
        del sys.argv[at:at + 2]
    args = hpt.parse_args(extra)
    os.makedirs(args.temp, exist_ok=True)
    if standalone:
        standalone_part(args, standalone)
        return
    lines = ["ParaView plugin benchmark, %s, load average %.1f at the start" % (
        time.strftime("%Y-%m-%d %H:%M"), os.getloadavg()[0])]
    parts = args.parts.split(",")
    if "A" in parts:
        part_a(args, lines)
    for part in ("B", "C"):
        if part in parts:
            part_same_frame(args, lines, part)
    lines.append("")
    lines.append("load average %.1f at the end" % os.getloadavg()[0])
    text = "\n".join(lines)
    print(text)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    main()
