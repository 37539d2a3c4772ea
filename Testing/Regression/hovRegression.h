/**
 * @file hovRegression.h
 * @brief The scene and the two comparisons of the VTK-convention regression tests.
 *
 * Each Test<Name>.cxx here describes one scene (a bundled dataset, a render
 * mode, an opacity semantics, isosurfaces, clipping) and calls Run(), which
 *  1. reads the dataset given by "-data <file>" (DATA{} in CMakeLists.txt),
 *  2. renders it with vtkHighOrderVolumeMapper in an offscreen window from
 *     vtkHighOrderOffscreenWindow (X if DISPLAY is set, Mesa EGL if not),
 *  3. checks the baseline given by "-V" exists and has the image's size (a
 *     clear message and a failure otherwise, the candidate written to "-T"),
 *  4. compares with vtkRegressionTestImage (VTK's comparison, threshold 0.15;
 *     on failure VTK writes the candidate and a difference image to "-T"),
 *  5. compares strictly, pixel by pixel (vtkHighOrderImageComparison; on
 *     failure the candidate <Name>.png and <Name>.strict-diff.png go to "-T").
 * Both must pass. "-perturb <f>" scales the opacity unit distance by 1 + f: a
 * deliberate, physically small change the strict comparison must catch
 * (Testing/Regression/CheckHarness.cmake).
 *
 * Strict tolerances (Tolerance(); measured and argued in the README,
 * "Regression tests"): CPU_ACCURATE and RAY_CAST must reproduce their baseline
 * exactly. Their float image is computed with the same operations on every
 * x86-64 CPU (baseline x86-64, kernels compiled with -ffp-contract=off) but
 * one: the thin series' Horner steps are fused multiply-adds where the CPU has
 * FMA (hovThinSeries.h: FusedSeries); "-separate-series" forces the rounding
 * of a CPU without, and hov.RegressionSeparateSeries-* checks that it
 * reproduces every baseline. glibc's libm may pick FMA variants of
 * exp/log/pow, which could differ in the last bit of a double, and the float
 * image is unchanged with those variants disabled (measured); the display of the float image by
 * llvmpipe is a conversion to 8 bits. OPENGL_PROJECTION: llvmpipe compiles the
 * shaders for the host CPU (vector width, instruction set), which moves a few
 * pixels by one level: at most 1 level on at most 0.2% of the pixels.
 */
#ifndef hovRegression_h
#define hovRegression_h

#include <string> // names
#include <vector> // isosurfaces and clipping planes

namespace hovRegression
{
/// One test's scene. Transfer function: the seven nodes of the comparison tools
/// (highordervolume.render_tools.DEFAULT_NODES) over the array's range.
struct Scene
{
  std::string Name;      ///< the test's name (baseline <Name>.png)
  std::string Array;     ///< point array rendered
  int RenderMode = 0;    ///< vtkHighOrderVolumeMapper::RenderModeType
  int Semantics = 1;     ///< OpacitySemanticsType (default VTK_UNSTRUCTURED)
  int ColorMethod = 3;   ///< ProjectionColorMethodType (OPENGL_PROJECTION)
  int Width = 128, Height = 128;
  double Azimuth = 30, Elevation = 20, Zoom = 1.3; ///< after the default fit (degrees)
  double UnitFraction = 0.02;                      ///< unit distance / bounding-box diagonal
  double RayCastTolerance = 1e-3;
  /// Isosurfaces: value as a fraction of the array's range, r, g, b, opacity.
  std::vector<double> Isosurfaces;
  /// Clipping planes: origin as fractions of the bounds, then the normal (6 values each).
  std::vector<double> ClipPlanes;
};

/// The strict comparison's allowance for a render mode: largest per-pixel
/// difference (8-bit levels) and the fraction of pixels allowed to differ at all.
struct Allowance
{
  int Levels = 0;
  double PixelFraction = 0.0;
};
Allowance Tolerance(int renderMode);

/// Renders @p scene and compares it with its baseline; EXIT_SUCCESS or EXIT_FAILURE.
int Run(int argc, char* argv[], const Scene& scene);
}

#endif
