/**
 * @file hovTestScenes.h
 * @brief Shared set-up of the VTK-level tests (TestBadInput*, TestOpenGL*,
 * TestCompareVTK, TestWitness, TestAnalytic*): the check bookkeeping, the
 * mapper + volume + transfer function + message observer every test starts
 * from, transfer functions, cameras, offscreen windows, opaque boxes and the
 * bundled bracket mesh.
 *
 * Includes hovTestMeshes.h (hand-built meshes) and hovTestImages.h (float
 * images, captures, statistics), so a test needs only this header.
 */
#ifndef hovTestScenes_h
#define hovTestScenes_h

#include "hovTestImages.h"
#include "hovTestMeshes.h"

#include "vtkHighOrderVolumeMapper.h"

#include "vtkColorTransferFunction.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkSmartPointer.h"
#include "vtkTestErrorObserver.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <memory> // BracketScene

#include <string>

class vtkActor;
class vtkCamera;
class vtkCommand;
class vtkObject;
class vtkRenderWindow;
class vtkRenderer;

namespace hovTest
{
//------------------------------------------------------------------------------
// Checks and messages.

/// Failure bookkeeping: every check prints its verdict and the measured values.
struct Checker
{
  int Failures = 0;
  int Checks = 0;
  bool Check(bool ok, const std::string& what);
  /// Prints the totals; EXIT_SUCCESS if no check failed.
  int Result() const;
};

/// The text of VTK error/warning messages without their "ERROR: In file, line"
/// headers (printing those would make ctest's FAIL_REGULAR_EXPRESSION fire).
std::string Msg(const std::string& raw);

/// "CPU_ACCURATE", "OPENGL_PROJECTION" or "RAY_CAST" for a mapper RenderMode.
const char* ModeName(int mode);

/// The argument following @p flag ("-D" data dir, "-T" temporary dir), or @p fallback.
std::string ArgAfter(int argc, char* argv[], const char* flag, const std::string& fallback);

/// Adds @p observer to the error and warning events of @p object.
void ObserveMessages(vtkObject* object, vtkCommand* observer);

//------------------------------------------------------------------------------
// Transfer functions.

/// A colour and an opacity function in a vtkVolumeProperty (linear, unshaded).
struct TF
{
  vtkSmartPointer<vtkColorTransferFunction> Color =
    vtkSmartPointer<vtkColorTransferFunction>::New();
  vtkSmartPointer<vtkPiecewiseFunction> Opacity = vtkSmartPointer<vtkPiecewiseFunction>::New();
  vtkSmartPointer<vtkVolumeProperty> Property = vtkSmartPointer<vtkVolumeProperty>::New();
  TF();
};

/// Colour red->green->blue over [0, 1.75], opacity 0.2 -> 0.8 with a bump.
void DefaultTF(TF& tf, double unit = 0.5);

/// Constant colour @p rgb and opacity @p opacity (one node each, at s = 0),
/// unit distance @p unit.
void ConstantTF(TF& tf, const double rgb[3], double opacity, double unit);

/// Colour linear from @p colorA at @p sA to @p colorB at @p sB, opacity linear
/// from @p opacityA to @p opacityB over the same nodes, unit distance 1, and
/// the lighting coefficients @p ka, @p kd, @p ks, @p power (Shade untouched).
void LinearShadingTF(TF& tf, double sA, double sB, const double colorA[3],
  const double colorB[3], double opacityA, double opacityB, double ka, double kd, double ks,
  double power);

/// The five nodes over the bracket's von_mises range [0, 170] (every opacity
/// node is also a colour node), unit distance @p unit.
void BracketTF(TF& tf, double unit);

//------------------------------------------------------------------------------
// The mapper under test.

/// The one warning of a volume with Shade on and isosurfaces in CPU_ACCURATE
/// (hov::PropertyAudit: the volume itself is not shaded there).
constexpr const char* IsoShadeWarning =
  "Shade (volume shading) is not applied in CPU_ACCURATE mode with isosurfaces";

/// Counts (and keeps the text of) the warnings and errors of what it observes.
class MessageCounter : public vtkCommand
{
public:
  static MessageCounter* New() { return new MessageCounter; }
  void Execute(vtkObject*, unsigned long event, void* data) override;
  void Clear();
  int Warnings = 0, Errors = 0;
  std::string Text;
};

/// A vtkHighOrderVolumeMapper in a vtkVolume with the property of Tf, and an
/// observer of the mapper's errors and warnings. The transfer function and the
/// mapper's settings are up to the test.
struct VolumeScene
{
  vtkNew<vtkHighOrderVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkTest::ErrorObserver> Observer;
  TF Tf;
  /// @p input (if not null) becomes the mapper's input data.
  explicit VolumeScene(vtkUnstructuredGrid* input = nullptr);
  /// No error and no warning observed (since the last Observer->Clear()).
  bool NoMessages() const;
  /// No error, and no warning but at most one containing @p allowed.
  bool NoMessagesBut(const std::string& allowed) const;
};

//------------------------------------------------------------------------------
// Cameras.

/// Oblique perspective view of the unit cube.
void ObliqueCamera(vtkCamera* cam);

/// Orthographic view of the unit cube along -z; with parallel scale 1 and a
/// square image of N pixels the cube covers pixel centres N/4 .. 3N/4-1 in x
/// and y (for N a multiple of 4 no pixel centre lies on an edge).
///
/// @p dx shifts the view in x. AxisOrthoShift (1/8192) keeps every pixel
/// centre of a 1..4096-pixel square image off the planes x = y and x = y +- 1/2
/// (the interior faces of UnitBlock(2) parallel to the view direction), so no
/// ray lies exactly in a face.
constexpr double AxisOrthoShift = 1.0 / 8192.0;
void AxisOrthoCamera(vtkCamera* cam, double scale = 1.0, double dx = 0.0);

/// World x (or y) of pixel centre i of an N-pixel axis under AxisOrthoCamera.
double OrthoPixelCoord(int i, int n, double scale = 1.0, double aspect = 1.0, double dx = 0.0);

//------------------------------------------------------------------------------
// Renderers and windows.

/// A renderer with a black background showing @p cam.
vtkSmartPointer<vtkRenderer> BlackRenderer(vtkCamera* cam);

/// An offscreen window of @p w x @p h holding @p ren (if not null); @p multiSamples >= 0
/// sets the number of multisamples (-1: VTK's default). From vtkHighOrderOffscreenWindow:
/// X if DISPLAY is set (Xvfb), Mesa EGL if not (the headless twins hov.Headless.Cxx.*);
/// the test exits with a failure if there is none.
vtkSmartPointer<vtkRenderWindow> OffscreenWindow(
  vtkRenderer* ren, int w, int h, int multiSamples = -1);

/// The float images of @p mapper rendered in @p win with CPU_ACCURATE, then
/// with OPENGL_PROJECTION and colour method M3 (the mapper is left in that mode).
struct CPUAndProjection
{
  Image CPU, Projection;
};
CPUAndProjection RenderCPUAndProjectionM3(vtkHighOrderVolumeMapper* mapper, vtkRenderWindow* win);

/// An unlit box actor over @p b (xmin,xmax,ymin,ymax,zmin,zmax) of flat
/// colour @p rgb and opacity @p opacity.
vtkSmartPointer<vtkActor> BoxActor(const double b[6], const double rgb[3], double opacity = 1.0);

//------------------------------------------------------------------------------
// Data.

/// The bundled CalculiX bracket (bracket_tet4_ccx.vtu in the "-D" directory,
/// 56071 linear tets) with "von_mises" as the active point scalars; its path
/// in @p file if given.
vtkSmartPointer<vtkUnstructuredGrid> LoadBracket(
  int argc, char* argv[], std::string* file = nullptr);

/// The bracket (LoadBracket) in a VolumeScene with BracketTF(unit 2); null
/// after a failed check if it could not be loaded.
std::unique_ptr<VolumeScene> BracketScene(Checker& ck, int argc, char* argv[]);

/// The oblique perspective view of the bracket the interaction tests use.
void BracketCamera(vtkCamera* cam);

/// The non-interactive render of @p win's current view by @p mapper
/// (AutoAdjustImageSampleDistance off, ProgressiveTime 0, the still rate):
/// the reference of the interaction tests; the mapper's settings restored.
Image NonInteractiveRender(vtkRenderWindow* win, vtkHighOrderVolumeMapper* mapper);
}

#endif
