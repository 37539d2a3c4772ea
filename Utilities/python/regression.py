"""VTK-style regression image tests with a strict comparison next to VTK's.

``check_window(window, baseline, temp_dir, name)`` does what the module's C++ regression tests
(Testing/Regression/hovRegression.cxx) do with a rendered vtkRenderWindow:

1. the baseline PNG must exist and have the window's size (else: a message, and the
   candidate image written to ``temp_dir/<name>.png``);
2. VTK's comparison: vtkTesting.RegressionTest(0.15), as vtkRegressionTestImage and
   vtkmodules.test.Testing.compareImage do (it renders the window again; on failure it writes
   the candidate and a difference image to temp_dir);
3. the strict comparison of that same frame: vtkHighOrderImageComparison, at most ``levels``
   (8-bit) per pixel and at most ``pixel_fraction`` of the pixels differing at all (on failure:
   ``<name>.png`` and ``<name>.strict-diff.png`` in temp_dir).

It returns (passed, report lines). Our tolerances: exact (0, 0.0) for CPU_ACCURATE and RAY_CAST,
(1, 0.002) for OPENGL_PROJECTION (README, "Regression tests").

    from highordervolume.regression import check_window
    ok, lines = check_window(window, "Baseline/MyTest.png", "Temporary", "MyTest")
"""
import os

from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
from vtkmodules.vtkTestingRendering import vtkTesting

from .vtkRenderingHighOrderVolume import vtkHighOrderImageComparison

VTK_THRESHOLD = 0.15  # vtkRegressionTestImage's


def _write_png(image, path):
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()
    return writer.GetErrorCode() == 0


def _baseline_problem(baseline, width, height):
    if not os.path.isfile(baseline):
        return "baseline '%s' not found; check the candidate and copy it there" % baseline
    reader = vtkPNGReader()
    if not reader.CanReadFile(baseline):
        return "baseline '%s' is not a PNG file" % baseline
    reader.SetFileName(baseline)
    reader.Update()
    w, h, _ = reader.GetOutput().GetDimensions()
    if (w, h) != (width, height):
        return "baseline '%s' is %d x %d pixels, the rendered image %d x %d" % (
            baseline, w, h, width, height)
    return None


def check_window(window, baseline, temp_dir, name, levels=0, pixel_fraction=0.0):
    """VTK's comparison and the strict one of ``window`` against ``baseline``; see the module."""
    os.makedirs(temp_dir, exist_ok=True)
    capture = vtkWindowToImageFilter()
    capture.SetInput(window)
    capture.SetInputBufferTypeToRGB()
    capture.ReadFrontBufferOff()
    lines = []
    candidate_path = os.path.join(temp_dir, name + ".png")
    width, height = window.GetSize()
    problem = _baseline_problem(baseline, width, height)
    if problem:
        # Rendered as vtkTesting renders it (a second render through the capture filter).
        window.SwapBuffersOff()
        window.Render()
        capture.ShouldRerenderOn()
        capture.Update()
        window.SwapBuffersOn()
        lines.append("%s FAILED: %s" % (name, problem))
        if _write_png(capture.GetOutput(), candidate_path):
            lines.append("  candidate image written to %s" % candidate_path)
        return False, lines

    testing = vtkTesting()
    for arg in ("-V", os.path.abspath(baseline), "-T", os.path.abspath(temp_dir)):
        testing.AddArgument(arg)
    testing.SetRenderWindow(window)
    vtk_ok = testing.RegressionTest(VTK_THRESHOLD) == vtkTesting.PASSED
    lines.append("VTK's comparison (vtkTesting, threshold %g): %s (error %g)" % (
        VTK_THRESHOLD, "passed" if vtk_ok else "FAILED", testing.GetImageDifference()))

    capture.ShouldRerenderOff()
    capture.Update()
    reader = vtkPNGReader()
    reader.SetFileName(baseline)
    reader.Update()
    strict = vtkHighOrderImageComparison()
    strict.SetTolerance(levels)
    strict.SetAllowedPixels(int(pixel_fraction * width * height))
    strict_ok = strict.Compare(reader.GetOutput(), capture.GetOutput())
    lines.append("strict comparison: " + strict.GetSummary())
    if not strict_ok:
        if _write_png(capture.GetOutput(), candidate_path):
            lines.append("  candidate image written to %s" % candidate_path)
        diff_path = os.path.join(temp_dir, name + ".strict-diff.png")
        if strict.GetDifferenceImage() is not None and _write_png(strict.GetDifferenceImage(),
                                                                  diff_path):
            lines.append("  difference image written to %s" % diff_path)
    return vtk_ok and strict_ok, lines
