"""The example scripts of Utilities/examples run and write what they promise.

Runs, at a small size, render_vtu.py and compare_projected_tetrahedra.py
(PNG + float .vti written, the float image is non-trivial and free of NaN,
the comparison prints its numbers), and the example spec bracket_spec.json
through both batch entry points (made small by a copy with a smaller image;
the data path stays relative to the examples folder), so the examples never rot.
"""
import json
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLImageDataReader

import highordervolume

from hov_pytest import arguments, check, finish
HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLES = os.path.join(HERE, "..", "..", "Utilities", "examples")


def float_image(path):
    if not os.path.isfile(path):
        return None
    reader = vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    array = reader.GetOutput().GetPointData().GetArray("RGBA")
    return None if array is None else vtk_to_numpy(array)


def check_image(path, what):
    rgba = float_image(path)
    ok = rgba is not None and not np.isnan(rgba).any() and rgba[:, 3].max() > 0.2
    check(ok and os.path.isfile(path[:-4] + ".png"),
          "%s: PNG and float image written, finite, max alpha %s" % (
              what, "-" if rgba is None else "%.3f" % rgba[:, 3].max()))


def run(command, cwd, env, what):
    proc = subprocess.run(command, capture_output=True, text=True, env=env, cwd=cwd)
    check(proc.returncode == 0, "%s: exit %d %s" % (
        what, proc.returncode, proc.stderr.strip()[-300:] if proc.returncode else ""))
    check("WARN|" not in proc.stderr and "ERR|" not in proc.stderr,
          "%s: no VTK warning or error %s" % (what, proc.stderr.strip()[-300:]))
    return proc


def main():
    args = arguments()
    folder = os.path.join(os.path.abspath(args.temp), "batch_examples")
    os.makedirs(folder, exist_ok=True)
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([
        os.path.dirname(os.path.dirname(highordervolume.__file__)), EXAMPLES,
        env.get("PYTHONPATH", "")])
    data = os.path.join(os.path.abspath(args.data), "bracket_tet4_ccx.vtu")
    size = ["--size", "96", "72"]

    run([sys.executable, os.path.join(EXAMPLES, "render_vtu.py"), "--data", data,
         "--out", "render"] + size, folder, env, "render_vtu.py")
    check_image(os.path.join(folder, "render.vti"), "render_vtu.py")

    proc = run([sys.executable, os.path.join(EXAMPLES, "compare_projected_tetrahedra.py"),
                "--data", data, "--out", "cmp"] + size, folder, env,
               "compare_projected_tetrahedra.py")
    check_image(os.path.join(folder, "cmp_ours.vti"), "compare_projected_tetrahedra.py")
    check(os.path.isfile(os.path.join(folder, "cmp_pt.png")) and "mean |diff|" in proc.stdout,
          "comparison printed: " + proc.stdout.strip())

    with open(os.path.join(EXAMPLES, "bracket_spec.json")) as f:
        spec = json.load(f)
    spec["image"] = {"width": 96, "height": 72}
    spec["data"] = os.path.join(os.path.abspath(EXAMPLES), spec["data"])
    small = os.path.join(folder, "bracket_spec_small.json")
    with open(small, "w") as f:
        json.dump(spec, f)
    exe = os.environ.get("HOV_BATCH_RENDER") or os.path.join(
        os.path.dirname(os.path.dirname(os.path.abspath(args.temp))), "bin", "hovBatchRender")
    images = []
    for tool, command in (("python", [sys.executable, "-m", "highordervolume.batch"]),
                          ("cxx", [exe])):
        vti = os.path.join(folder, spec["output"]["vti"])
        if os.path.exists(vti):
            os.remove(vti)
        run(command + [small], folder, env, "bracket_spec.json with " + tool)
        check_image(vti, "bracket_spec.json with " + tool)
        images.append(float_image(vti))
    check(all(i is not None for i in images) and np.array_equal(images[0], images[1]),
          "bracket_spec.json: both entry points give the same float image")
    return finish()


if __name__ == "__main__":
    sys.exit(main())
