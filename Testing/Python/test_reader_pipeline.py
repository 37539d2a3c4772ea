"""Reader -> vtkHighOrderVolumeMapper -> vtkVolume -> render, from Python.

Checks pixel values of the float image of the bundled bracket (56071 linear
tetrahedra) against an independent integration along a few rays: the field is
probed with vtkProbeFilter at 40000 points along each pixel's ray (ray built
here from the camera parameters, not by the module) and the optical depth is
integrated with the trapezoid rule. With a constant colour c the exact pixel
is (c A, A), A = 1 - exp(-integral tau dt), tau = a(s)/u (VTK-unstructured).
"""
import math
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL factory overrides)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkProbeFilter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer, vtkVolume,
                                         vtkVolumeProperty, vtkWindowToImageFilter)

import highordervolume
from highordervolume.offscreen import offscreen_window

from hov_pytest import arguments, check, FAILURES


def pixel_ray(camera, i, j, width, height):
    """Orthographic ray through the centre of pixel (i, j), from camera geometry."""
    pos = np.array(camera.GetPosition())
    focal = np.array(camera.GetFocalPoint())
    forward = focal - pos
    forward /= np.linalg.norm(forward)
    up = np.array(camera.GetViewUp())
    right = np.cross(forward, up)
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    half_h = camera.GetParallelScale()
    half_w = half_h * width / height
    x = (2.0 * (i + 0.5) / width - 1.0) * half_w
    y = (2.0 * (j + 0.5) / height - 1.0) * half_h
    near = camera.GetClippingRange()[0]
    origin = pos + x * right + y * up + near * forward
    return origin, forward


def reference_alpha(grid, opacity, unit, origin, direction, length, samples=40000):
    points = vtkPoints()
    t = np.linspace(0.0, length, samples)
    for tk in t:
        points.InsertNextPoint(*(origin + tk * direction))
    line = vtkPolyData()
    line.SetPoints(points)
    probe = vtkProbeFilter()
    probe.SetInputData(line)
    probe.SetSourceData(grid)
    probe.Update()
    out = probe.GetOutput()
    s = vtk_to_numpy(out.GetPointData().GetArray("von_mises"))
    valid = vtk_to_numpy(out.GetPointData().GetArray(probe.GetValidPointMaskArrayName()))
    tau = np.array([opacity.GetValue(v) / unit for v in s]) * (valid > 0)
    depth = np.trapz(tau, t)
    return 1.0 - math.exp(-depth), int(valid.sum())


def main():
    args = arguments()

    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(args.data, "bracket_tet4_ccx.vtu"))
    reader.Update()
    grid = reader.GetOutput()
    grid.GetPointData().SetActiveScalars("von_mises")
    lo, hi = grid.GetPointData().GetArray("von_mises").GetRange()

    colour = (1.0, 0.5, 0.25)
    ctf = vtkColorTransferFunction()
    ctf.AddRGBPoint(lo, *colour)
    ctf.AddRGBPoint(hi, *colour)
    otf = vtkPiecewiseFunction()
    otf.AddPoint(lo, 0.02)
    otf.AddPoint(30.0, 0.1)    # opacity nodes that are not colour nodes
    otf.AddPoint(60.0, 0.02)
    otf.AddPoint(hi, 0.4)
    unit = 4.0
    prop = vtkVolumeProperty()
    prop.SetColor(ctf)
    prop.SetScalarOpacity(otf)
    prop.SetScalarOpacityUnitDistance(unit)

    mapper = highordervolume.vtkHighOrderVolumeMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    mapper.SetOpacitySemanticsToVTKUnstructured()
    mapper.SetCellOrderingToPerPixelSort()
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)

    width, height = 160, 120
    ren = vtkRenderer()
    ren.AddVolume(volume)
    win = offscreen_window(width, height)  # X if DISPLAY is set, Mesa EGL if not
    win.AddRenderer(ren)
    cam = ren.GetActiveCamera()
    cam.ParallelProjectionOn()
    cam.SetFocalPoint(50, 30, 40)
    cam.SetPosition(50 + 150, 30 + 120, 40 + 100)
    cam.SetViewUp(0, 0, 1)
    ren.ResetCamera()
    ren.ResetCameraClippingRange()
    win.Render()

    image = mapper.GetFloatImage()
    check(image.GetDimensions()[:2] == (width, height), "float image has the viewport size")
    rgba = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, 4).astype(float)
    check(np.isfinite(rgba).all(), "no NaN/Inf pixel")
    alpha = rgba[:, :, 3]
    check(alpha.min() >= 0.0 and alpha.max() <= 1.0, "0 <= alpha <= 1")
    covered = alpha > 1e-4
    check(covered.sum() > 0.2 * width * height, "the bracket covers part of the image (%d px)" % covered.sum())
    check(alpha.max() > 0.3, "some pixels are substantially opaque (max %.3f)" % alpha.max())
    ratio_err = max(np.abs(rgba[:, :, c] - colour[c] * alpha).max() for c in range(3))
    check(ratio_err < 1e-6, "constant colour: premultiplied RGB = c * alpha (max err %.2e)" % ratio_err)

    # Independent integration along the rays of a few covered pixels.
    jj, ii = np.nonzero(covered)
    rng = np.random.default_rng(7)
    picks = rng.choice(len(ii), size=6, replace=False)
    near, far = cam.GetClippingRange()
    worst = 0.0
    for k in picks:
        i, j = int(ii[k]), int(jj[k])
        origin, direction = pixel_ray(cam, i, j, width, height)
        ref, inside = reference_alpha(grid, otf, unit, origin, direction, far - near)
        err = abs(ref - alpha[j, i])
        worst = max(worst, err)
        print("  pixel (%3d,%3d): mapper %.6f reference %.6f (%d samples inside)" % (i, j, alpha[j, i], ref, inside))
    check(worst < 2e-3, "alpha matches the probed integral at sampled pixels (max err %.2e)" % worst)

    # The on-screen image is the float image over the black background.
    grab = vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    screen = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).reshape(height, width, 3) / 255.0
    screen_err = np.abs(screen - rgba[:, :, :3]).max()
    check(screen_err <= 1.5 / 255.0, "screen = float image over black (max err %.4f)" % screen_err)

    # A numpy view of the published array keeps its frame: the next frame
    # (rewritten in place only when nobody holds the array) publishes a new one.
    view = vtk_to_numpy(image.GetPointData().GetScalars())
    kept = view.copy()
    cam.Azimuth(25)
    win.Render()
    after = vtk_to_numpy(mapper.GetFloatImage().GetPointData().GetScalars())
    check(np.array_equal(view, kept), "a held numpy view keeps the previous frame")
    check(not np.array_equal(after, kept) and np.isfinite(after).all(),
          "the next frame is a new, finite image")

    if FAILURES:
        print("%d check(s) failed" % len(FAILURES))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
