"""Batch renderer: malformed specs are rejected, naming the field at fault.

Each case is a valid spec with one defect (missing data, missing file, wrong
types, a bad enum value, a wrong camera arity, an unknown field, a missing
array, an out-of-range component, invalid JSON, ...). Both entry points
(``python3 -m highordervolume.batch`` and ``hovBatchRender``) must exit with
code 2, print a message containing the expected "<field>: <text>", and write
no output. The valid base spec must render (exit 0), so the cases fail for
their defect only. Unknown fields are errors (documented in README
"Batch rendering"); keys starting with "_" are comments. Render and output
failures (an unwritable output, a camera that defines no view) exit with 1.
"""
import copy
import json
import os
import subprocess
import sys

import highordervolume

from hov_pytest import arguments, check, finish


def base_spec(data):
    return {
        "_comment": "a valid spec; each case breaks one thing",
        "data": data,
        "array": {"name": "von_mises"},
        "image": {"width": 24, "height": 16},
        "camera": {"azimuth": 10},
        "transfer_function": {"color": [[0, 0, 0, 1], [170, 1, 0, 0]],
                              "opacity": [[0, 0.1], [170, 0.8]]},
        "output": {"vti": "out.vti"},
    }


def set_path(spec, path, value):
    keys = path.split(".")
    node = spec
    for k in keys[:-1]:
        node = node[k]
    if value is DELETE:
        del node[keys[-1]]
    else:
        node[keys[-1]] = value


DELETE = object()

# (name, edits [(dotted path, value)], expected message fragment)
CASES = [
    ("missing data", [("data", DELETE)], "data: expected a string, got nothing"),
    ("data file absent", [("data", "no_such_file.vtu")], "data: cannot read"),
    ("data wrong type", [("data", 3)], "data: expected a string, got a number"),
    ("array missing", [("array", DELETE)], "array: expected an object, got nothing"),
    ("array unknown", [("array.name", "no_such_array")], "array.name: no point array 'no_such_array'"),
    ("component too big", [("array.component", 1)], "array.component: 1 but 'von_mises' has 1"),
    ("association enum", [("array.association", "vertex")],
     "array.association: unknown value 'vertex' (expected one of: point, cell)"),
    ("camera arity", [("camera", {"position": [1, 2], "focal_point": [0, 0, 0]})],
     "camera.position: expected 3 numbers, got 2"),
    ("camera element type", [("camera", {"position": [1, "2", 3], "focal_point": [0, 0, 0]})],
     "camera.position[1]: expected a number, got a string"),
    ("camera focal point missing", [("camera", {"position": [1, 2, 3]})],
     "camera.focal_point: required when camera.position is given"),
    ("camera unknown field", [("camera", {"positon": [1, 2, 3]})],
     "camera.positon: unknown field"),
    ("zoom not positive", [("camera", {"zoom": 0})], "camera.zoom: expected a positive number"),
    ("view angle type", [("camera", {"view_angle": "wide"})],
     "camera.view_angle: expected a number, got a string"),
    ("top-level unknown", [("colour_map", "jet")], "colour_map: unknown field"),
    ("projection enum", [("projection", {"type": "fisheye"})],
     "projection.type: unknown value 'fisheye' (expected one of: perspective, orthographic)"),
    ("render mode enum", [("render_mode", "gpu")],
     "render_mode: unknown value 'gpu' (expected one of: cpu_accurate, opengl_projection, "
     "ray_cast)"),
    ("render mode unsupported feature",
     [("render_mode", "opengl_projection"), ("isosurfaces", [{"value": 50}])],
     "render_mode: opengl_projection does not support isosurfaces or clipping"),
    ("ray cast unsupported feature",
     [("render_mode", "ray_cast"), ("isosurfaces", [{"value": 50}])],
     "render_mode: ray_cast does not support isosurfaces (use cpu_accurate)"),
    ("ray cast tolerance type", [("render_mode", "ray_cast"), ("ray_cast_tolerance", "fine")],
     "ray_cast_tolerance: expected a number, got a string"),
    ("ray cast tolerance range", [("ray_cast_tolerance", 0.5)],
     "ray_cast_tolerance: expected a number in [1e-12, 0.1]"),
    ("ray cast tolerance sign", [("ray_cast_tolerance", 0)],
     "ray_cast_tolerance: expected a positive number"),
    ("semantics enum", [("transfer_function.opacity_semantics", "linear")],
     "transfer_function.opacity_semantics: unknown value 'linear'"),
    ("emission enum", [("transfer_function.emission_model", 1)],
     "transfer_function.emission_model: expected a string, got a number"),
    ("colour node arity", [("transfer_function.color", [[0, 0, 0, 1], [170, 1, 0]])],
     "transfer_function.color[1]: expected 4 numbers, got 3"),
    ("opacity empty", [("transfer_function.opacity", [])],
     "transfer_function.opacity: expected a non-empty array of [s, a] nodes, got an empty array"),
    ("unit distance", [("transfer_function.unit_distance", -1)],
     "transfer_function.unit_distance: expected a positive number"),
    ("width type", [("image.width", "big")], "image.width: expected an integer, got a string"),
    ("height range", [("image.height", 0)], "image.height: expected an integer in [1, 16384], got 0"),
    ("clip plane arity", [("clipping", {"planes": [{"origin": [0, 0, 0], "normal": [1, 0]}]})],
     "clipping.planes[0].normal: expected 3 numbers, got 2"),
    ("depth range order", [("clipping", {"view_depth_range": [5, 1]})],
     "clipping.view_depth_range: expected [near, far] with near < far"),
    ("isosurface value", [("isosurfaces", [{"color": [1, 0, 0]}])],
     "isosurfaces[0].value: expected a number, got nothing"),
    ("output none", [("output", {})], "output: expected at least one of vti, png"),
    ("output unknown", [("output", {"jpg": "a.jpg"})], "output.jpg: unknown field"),
]


def run(command, path, env):
    return subprocess.run(command + [path], capture_output=True, text=True, env=env,
                          cwd=os.path.dirname(path))


def main():
    args = arguments()
    exe = os.environ.get("HOV_BATCH_RENDER") or os.path.join(
        os.path.dirname(os.path.dirname(os.path.abspath(args.temp))), "bin", "hovBatchRender")
    env = dict(os.environ)
    env["PYTHONPATH"] = os.path.dirname(os.path.dirname(highordervolume.__file__)) + \
        os.pathsep + env.get("PYTHONPATH", "")
    folder = os.path.join(os.path.abspath(args.temp), "batch_errors")
    os.makedirs(folder, exist_ok=True)
    data = os.path.join(os.path.abspath(args.data), "bracket_tet4_ccx.vtu")
    tools = (("python", [sys.executable, "-m", "highordervolume.batch"]), ("cxx", [exe]))
    out = os.path.join(folder, "out.vti")

    path = os.path.join(folder, "valid.json")
    with open(path, "w") as f:
        json.dump(base_spec(data), f)
    for tool, command in tools:
        if os.path.exists(out):
            os.remove(out)
        proc = run(command, path, env)
        check(proc.returncode == 0 and os.path.isfile(out),
              "valid base spec renders with %s (exit %d) %s" % (tool, proc.returncode,
                                                                proc.stderr.strip()[-200:]))

    # RAY_CAST renders cell scalars (issue 19): both tools accept and render
    # the combination (the bracket's von_mises averaged onto its cells).
    from vtkmodules.vtkFiltersCore import vtkPointDataToCellData
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(data)
    to_cells = vtkPointDataToCellData()
    to_cells.SetInputConnection(reader.GetOutputPort())
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetFileName(os.path.join(folder, "cells.vtu"))
    writer.SetInputConnection(to_cells.GetOutputPort())
    writer.Write()
    spec = base_spec(os.path.join(folder, "cells.vtu"))
    spec["array"]["association"] = "cell"
    spec["render_mode"] = "ray_cast"
    path = os.path.join(folder, "ray_cast_cells.json")
    with open(path, "w") as f:
        json.dump(spec, f)
    for tool, command in tools:
        if os.path.exists(out):
            os.remove(out)
        proc = run(command, path, env)
        check(proc.returncode == 0 and os.path.isfile(out),
              "ray_cast with cell scalars renders with %s (exit %d) %s" % (
                  tool, proc.returncode, proc.stderr.strip()[-200:]))

    bodies = []
    for name, edits, expected in CASES:
        spec = copy.deepcopy(base_spec(data))
        for key, value in edits:
            set_path(spec, key, value)
        bodies.append((name, json.dumps(spec), expected))
    bodies.append(("invalid JSON", '{"data": "x.vtu", "array": "a",,}', "(file): not valid JSON"))
    # Non-finite numbers: NaN/Infinity are not JSON and a literal beyond the
    # double range is not a number (jsoncpp's words): both refuse the file.
    text = json.dumps(base_spec(data))
    bodies += [
        ("NaN token", text.replace('"azimuth": 10', '"azimuth": NaN'), "(file): not valid JSON"),
        ("Infinity token", text.replace('"azimuth": 10', '"azimuth": -Infinity'),
         "(file): not valid JSON"),
        ("overflowing number", text.replace('"azimuth": 10', '"azimuth": 1e999'),
         "'1e999' is not a number"),
        ("overflowing integer", text.replace('"width": 24', '"width": -1e999'),
         "'-1e999' is not a number"),
    ]
    # Issue 21 finding 7: nesting beyond the parsers' limits and bytes that are
    # not UTF-8 are refused the same way (the C++ tool aborted on the first,
    # the Python one printed a traceback for both).
    bodies += [
        ("deeply nested JSON", "[" * 100000, "(file): not valid JSON"),
        ("not UTF-8", text.replace('"von_mises"', '"von_mis\xff"'), "(file): not valid JSON"),
    ]
    path = os.path.join(folder, "case.json")
    for name, body, expected in bodies:
        with open(path, "wb") as f:
            f.write(body.encode("utf-8", "surrogateescape") if "\xff" not in body
                    else body.encode("latin-1"))
        for tool, command in tools:
            if os.path.exists(out):
                os.remove(out)
            proc = run(command, path, env)
            ok = proc.returncode == 2 and expected in proc.stderr and not os.path.exists(out)
            check(ok, "%s (%s): exit %d, message %r" % (name, tool, proc.returncode,
                                                         proc.stderr.strip()[:300]))
    # Render and output failures: exit 1 with a message, never 0 (finding 7).
    # A folder that does not exist; a camera that defines no view (its up
    # vector along the view direction), in every mode.
    failures = [("vti in a missing folder",
                 [("output", {"vti": os.path.join(folder, "no_such_dir", "a.vti")})],
                 "output.vti: cannot write"),
                ("png in a missing folder",
                 [("output", {"png": os.path.join(folder, "no_such_dir", "a.png")})],
                 "output.png: cannot write")]
    for mode in ("cpu_accurate", "opengl_projection", "ray_cast"):
        failures.append(("up vector along the view direction, " + mode,
                         [("render_mode", mode),
                          ("camera", {"position": [0, 0, 500], "focal_point": [0, 0, 0],
                                      "view_up": [0, 0, 1]})],
                         "render failed"))
    for name, edits, expected in failures:
        spec = copy.deepcopy(base_spec(data))
        for key, value in edits:
            set_path(spec, key, value)
        with open(path, "w") as f:
            json.dump(spec, f)
        for tool, command in tools:
            if os.path.exists(out):
                os.remove(out)
            proc = run(command, path, env)
            ok = proc.returncode == 1 and expected in proc.stderr and not os.path.exists(out)
            check(ok, "%s (%s): exit %d, message %r" % (name, tool, proc.returncode,
                                                         proc.stderr.strip()[-300:]))
    return finish()


if __name__ == "__main__":
    sys.exit(main())
