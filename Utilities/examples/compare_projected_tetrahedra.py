"""Render a tetrahedral .vtu with vtkHighOrderVolumeMapper and with VTK's
vtkProjectedTetrahedraMapper (same property, camera and window) and compare.

    /usr/bin/python3 Utilities/examples/compare_projected_tetrahedra.py --out cmp

writes cmp_ours.png, cmp_pt.png, cmp_ours.vti (float image) and prints the
mean and largest difference of the 8-bit RGB images. Our mapper uses the
VTK_UNSTRUCTURED opacity semantics here (extinction a(s)/u, what VTK's
unstructured mappers use), so the two differ by PT's approximations only
(per-tetrahedron averaged colour, 8-bit blending, approximate order).
"""
import argparse

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingVolume import vtkProjectedTetrahedraMapper

import highordervolume  # noqa: F401  (also loads the OpenGL2 overrides)
from highordervolume import vtkHighOrderVolumeMapper

import render_vtu


def rgb(image):
    return vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(np.float64)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", default=render_vtu.BRACKET)
    parser.add_argument("--array", default="von_mises")
    parser.add_argument("--size", type=int, nargs=2, default=(640, 480))
    parser.add_argument("--unit-distance", type=float, default=1.0)
    parser.add_argument("--out", default="compare")
    args = parser.parse_args(argv)
    grid = render_vtu.load(args.data, args.array)
    lo, hi = grid.GetPointData().GetArray(args.array).GetRange(-1)
    prop = render_vtu.make_property(lo, hi, args.unit_distance)

    ours = vtkHighOrderVolumeMapper()
    ours.SetInputData(grid)
    ours.SetOpacitySemanticsToVTKUnstructured()
    window = render_vtu.make_view(grid, ours, prop, args.size)
    window.Render()
    image_ours = render_vtu.save_png(window, args.out + "_ours.png")
    render_vtu.save_vti(ours.GetFloatImage(), args.out + "_ours.vti")

    pt = vtkProjectedTetrahedraMapper()
    pt.SetInputData(grid)
    window_pt = render_vtu.make_view(grid, pt, prop, args.size)
    window_pt.Render()
    image_pt = render_vtu.save_png(window_pt, args.out + "_pt.png")

    diff = np.abs(rgb(image_ours) - rgb(image_pt))
    print("ours vs vtkProjectedTetrahedraMapper, 8-bit RGB: mean |diff| %.2f, max %d, "
          "pixels differing by > 8: %.1f%%" % (diff.mean(), diff.max(),
                                             100.0 * (diff.max(axis=1) > 8).mean()))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
