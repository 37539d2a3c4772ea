"""Rendering without an X server (issue 18): the tools render every mode headless, with the
images they give on an X display, and fail with a message where they cannot render.

With an X display (the X pass runs under Xvfb):
  1. hovBatchRender and `python3 -m highordervolume.batch` render the bracket in every render
     mode (CPU_ACCURATE, RAY_CAST, OPENGL_PROJECTION in both opacity semantics) on the X
     display, with DISPLAY unset (Mesa EGL) and, for hovBatchRender, with HOV_OFFSCREEN=egl on
     the X display; the float images (.vti, "RGBA") must be bit-identical to the X ones (the
     measured maximum differences are printed).
  2. hov-compare renders one method of each kind (our CPU reference, projection and ray
     caster, VTK's projected tetrahedra, the unstructured ray caster, the GPU ray caster on a
     resampled grid) with DISPLAY unset: every image (.npy) equals the X one.
Both passes (the headless twin has no DISPLAY):
  3. vtkHighOrderOffscreenWindow from Python: the backend chosen (egl without DISPLAY), sizes 0
     and 65536 refused with a message, HOV_OFFSCREEN=nonsense refused.
  4. The demo (Utilities/hov_demo.py, small, the bracket only) in the headless pass: every
     mapper's PNG and the float images written.
  5. Bad environments, each a clear message and a non-zero exit code (not a signal), fast:
     a DISPLAY naming no X server; a DISPLAY whose server accepts the connection but never
     answers (a local TCP socket; HOV_DISPLAY_TIMEOUT=1); no EGL driver (DISPLAY unset,
     glvnd given no vendor); for hovBatchRender and the Python batch in OPENGL_PROJECTION,
     and hov-compare. An image size of 0 or 65536 in a spec: refused by both batch tools.
"""
import json
import os
import socket
import subprocess
import sys
import time

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLImageDataReader

import highordervolume  # noqa: F401
from highordervolume import vtkHighOrderOffscreenWindow
from highordervolume.offscreen import OffscreenError, backend_name, offscreen_window

from hov_pytest import arguments, check, finish

PYTHON = "/usr/bin/python3"


def build_dir(temp):
    return os.path.dirname(os.path.dirname(os.path.abspath(temp)))


def environment(display="keep", **extra):
    """The test's environment with DISPLAY kept, removed (None) or replaced, plus extra."""
    env = dict(os.environ)
    env.pop("HOV_OFFSCREEN", None)
    if display is None:
        env.pop("DISPLAY", None)
    elif display != "keep":
        env["DISPLAY"] = display
    env.update(extra)
    return env


def run(cmd, env, timeout=300):
    t0 = time.perf_counter()
    p = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=timeout)
    return p.returncode, p.stdout + p.stderr, time.perf_counter() - t0


def read_rgba(path):
    r = vtkXMLImageDataReader()
    r.SetFileName(path)
    r.Update()
    array = r.GetOutput().GetPointData().GetArray("RGBA")
    return None if array is None else vtk_to_numpy(array).astype(np.float64)


def spec(data, mode, semantics, out):
    return {"data": data, "array": "von_mises", "image": {"width": 80, "height": 64},
            "camera": {"view_up": [0, 0, 1], "azimuth": 35, "elevation": 25, "zoom": 1.2},
            "transfer_function": {
                "color": [[0, 0.23, 0.3, 0.75], [40, 0.55, 0.7, 1], [85, 0.87, 0.87, 0.87],
                          [170, 0.71, 0.02, 0.15]],
                "opacity": [[0, 0.05], [40, 0.15], [85, 0.5], [170, 0.95]],
                "unit_distance": 3.0, "opacity_semantics": semantics},
            "render_mode": mode, "output": {"vti": out}}


MODES = [("cpu_accurate", "vtk_unstructured"), ("ray_cast", "vtk_unstructured"),
         ("opengl_projection", "vtk_unstructured"), ("opengl_projection", "gpu_compatible")]


def batch_commands(temp):
    exe = os.environ.get("HOV_BATCH_RENDER") or os.path.join(build_dir(temp), "bin",
                                                             "hovBatchRender")
    return {"hovBatchRender": [exe],
            "python batch": [PYTHON, "-m", "highordervolume.batch"]}


def check_batch_headless_equals_x(args):
    """Acceptance 1 for both batch entry points: every mode, headless == X, bit for bit."""
    data = os.path.abspath(os.path.join(args.data, "bracket_tet4_ccx.vtu"))
    work = os.path.join(args.temp, "headless_batch")
    os.makedirs(work, exist_ok=True)
    envs = [("x11", environment()), ("no DISPLAY", environment(None)),
            ("HOV_OFFSCREEN=egl", environment(HOV_OFFSCREEN="egl"))]
    for tool, cmd in batch_commands(args.temp).items():
        for mode, semantics in MODES:
            images = {}
            for label, env in envs:
                if tool == "python batch" and label == "HOV_OFFSCREEN=egl":
                    continue  # the same window code as hovBatchRender's (the module's factory)
                tag = "%s_%s_%s_%s" % (tool.replace(" ", "_"), mode, semantics, label.split()[0])
                out = os.path.join(work, tag.replace("=", "_") + ".vti")
                path = os.path.join(work, tag.replace("=", "_") + ".json")
                with open(path, "w") as f:
                    json.dump(spec(data, mode, semantics, out), f)
                code, text, _ = run(cmd + [path], env)
                images[label] = read_rgba(out) if code == 0 and os.path.exists(out) else None
                check(code == 0 and images[label] is not None,
                      "%s %s (%s) renders with %s%s" % (tool, mode, semantics, label,
                                                        "" if code == 0 else ": " + text[-300:]))
            x = images["x11"]
            for label, image in images.items():
                if label == "x11" or x is None or image is None:
                    continue
                diff = float(np.abs(image - x).max())
                print("[measured] %s %s (%s): max |float image, %s - X| = %g" % (
                    tool, mode, semantics, label, diff))
                check(diff == 0.0 and image.any(), "%s %s (%s): %s image identical to X" % (
                    tool, mode, semantics, label))


def check_compare_headless_equals_x(args):
    """Acceptance 1 for hov-compare: our modes and VTK's mappers, headless == X."""
    data = os.path.abspath(os.path.join(args.data, "bracket_tet4_ccx.vtu"))
    methods = "hov_cpu_vtk,hov_proj_m3_vtk,hov_ray_vtk,vtk_pt,vtk_ugrc,hov_cpu_gpu,vtk_gpu_32"
    outs = {}
    for label, env in [("x11", environment()), ("no DISPLAY", environment(None))]:
        out = os.path.join(args.temp, "headless_compare_" + label.split()[0])
        code, text, _ = run([PYTHON, "-m", "highordervolume.compare", data, "von_mises",
                             "--size", "48", "48", "--frames", "1", "--resolutions", "32",
                             "--semantics", "vtk,gpu", "--methods", methods, "--out", out], env)
        check(code == 0, "hov-compare with %s%s" % (label, "" if code == 0 else ": " + text[-400:]))
        outs[label] = out
    for key in methods.split(","):
        name = "compare_%s.npy" % key
        paths = [os.path.join(outs[label], name) for label in ("x11", "no DISPLAY")]
        if not all(os.path.exists(p) for p in paths):
            check(False, "hov-compare %s: images written in both passes" % key)
            continue
        x, e = (np.load(p).astype(np.float64) for p in paths)
        diff = float(np.abs(e - x).max())
        print("[measured] hov-compare %s: max |headless - X| = %g" % (key, diff))
        check(diff == 0.0 and x.any(), "hov-compare %s: headless image identical to X" % key)


def check_factory(args):
    headless = not os.environ.get("DISPLAY")
    window = offscreen_window(32, 24)
    check(window.GetSize()[0] == 32 and window.GetSize()[1] == 24, "offscreen_window: 32 x 24")
    check(backend_name(window) == ("egl" if headless else "x11"),
          "offscreen_window chose %s (DISPLAY %s)" % (backend_name(window),
                                                      "unset" if headless else "set"))
    factory = vtkHighOrderOffscreenWindow()
    for w, h in [(0, 10), (10, 0), (65536, 10), (10, 65536), (-3, 5)]:
        win = factory.NewRenderWindow(w, h)
        check(win is None and "1..16384" in factory.GetErrorMessage(),
              "size %d x %d refused: %s" % (w, h, factory.GetErrorMessage()))
    try:
        offscreen_window(0, 0)
        check(False, "offscreen_window(0, 0) raises OffscreenError")
    except OffscreenError as exc:
        check("window size 0 x 0" in str(exc), "offscreen_window(0, 0) raises: %s" % exc)
    os.environ["HOV_OFFSCREEN"] = "nonsense"
    win = factory.NewRenderWindow(16, 16)
    del os.environ["HOV_OFFSCREEN"]
    check(win is None and "HOV_OFFSCREEN" in factory.GetErrorMessage(),
          "HOV_OFFSCREEN=nonsense refused: %s" % factory.GetErrorMessage())


class SilentServer:
    """A TCP port that accepts X connections and never answers (a hung X server)."""

    def __init__(self):
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        for number in range(180, 260):
            try:
                self.sock.bind(("127.0.0.1", 6000 + number))
                break
            except OSError:
                continue
        self.sock.listen(4)
        self.display = "127.0.0.1:%d" % (self.sock.getsockname()[1] - 6000)

    def close(self):
        self.sock.close()


def check_bad_environments(args):
    data = os.path.abspath(os.path.join(args.data, "bracket_tet4_ccx.vtu"))
    work = os.path.join(args.temp, "headless_bad")
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, "projection.json")
    with open(path, "w") as f:
        json.dump(spec(data, "opengl_projection", "vtk_unstructured",
                       os.path.join(work, "never.vti")), f)
    server = SilentServer()
    no_egl = os.path.join(work, "no_egl_vendor.json")  # glvnd: no EGL vendor library
    cases = [
        ("a DISPLAY naming no X server", environment(":97"), "cannot connect to the X server"),
        ("an X server that never answers", environment(server.display, HOV_DISPLAY_TIMEOUT="1"),
         "did not answer within 1 s"),
        ("no DISPLAY and no EGL", environment(None, __EGL_VENDOR_LIBRARY_FILENAMES=no_egl),
         "no OpenGL without X"),
    ]
    tools = dict(batch_commands(args.temp))
    compare = [PYTHON, "-m", "highordervolume.compare", data, "von_mises", "--size", "16", "16",
               "--frames", "1", "--methods", "hov_cpu_vtk", "--out", os.path.join(work, "cmp")]
    try:
        for label, env, message in cases:
            for tool, cmd in list(tools.items()) + [("hov-compare", None)]:
                full = compare if cmd is None else cmd + [path]
                code, text, seconds = run(full, env, timeout=120)
                check(code > 0 and message in text and seconds < 60,
                      "%s with %s: exit code %d (no signal), says '%s', %.1f s" % (
                          tool, label, code, message, seconds))
                if message not in text:
                    print(text[-600:])
    finally:
        server.close()
    for size in (0, 65536):
        sized = spec(data, "opengl_projection", "vtk_unstructured", os.path.join(work, "x.vti"))
        sized["image"] = {"width": size, "height": 64}
        p = os.path.join(work, "size_%d.json" % size)
        with open(p, "w") as f:
            json.dump(sized, f)
        for tool, cmd in tools.items():
            code, text, _ = run(cmd + [p], environment())
            check(code == 2 and "image.width" in text,
                  "%s with an image width of %d: exit code %d, names image.width" % (
                      tool, size, code))


def check_demo_headless(args):
    demo = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir,
                        "Utilities", "hov_demo.py")
    out = os.path.join(args.temp, "headless_demo")
    code, text, seconds = run([PYTHON, demo, "--out", out, "--size", "48", "--frames", "3",
                               "--no-issue4"], environment(None))
    check(code == 0, "the demo renders with DISPLAY unset (%.1f s)%s" % (
        seconds, "" if code == 0 else ": " + text[-600:]))
    expected = ["hov_demo_%s.png" % k for k in (
        "hov_pixelsort", "hov_visibility", "hov_cellcentre", "projected_tetrahedra",
        "projected_tetrahedra_stein", "ug_raycast", "hov_projection_m1", "hov_projection_m3",
        "hov_gpu", "montage")] + ["hov_demo_reference.vti", "hov_demo_gpu.vti",
                                  "hov_demo_table.md"]
    missing = [f for f in expected if not os.path.exists(os.path.join(out, f))]
    check(not missing, "the demo wrote every image and table%s" % (
        "" if not missing else " (missing: %s)" % ", ".join(missing)))


def main():
    args = arguments()
    os.makedirs(args.temp, exist_ok=True)
    check_factory(args)
    check_bad_environments(args)
    if os.environ.get("DISPLAY"):
        check_batch_headless_equals_x(args)
        check_compare_headless_equals_x(args)
    else:
        print("note: no DISPLAY (the headless pass): the X comparisons run in the X pass")
        check_demo_headless(args)
    return finish()


if __name__ == "__main__":
    sys.exit(main())
