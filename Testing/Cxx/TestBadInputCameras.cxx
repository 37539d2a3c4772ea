// Issue 21, findings 2, 4, 5 and 6, in every render mode, through RenderImage
// and in a window. The rule under test (vtkHighOrderVolumeMapperChecks.cxx):
// RenderImage returns 0 with an error when it cannot render, else 1; a window
// render gives the same error; an empty image always comes with a warning; the
// float image never holds NaN or Inf.
//  - finding 2: a view angle of 0 (VTK clamps it to 1e-8 degrees) magnifies
//    far-off cells to window coordinates beyond INT_MAX; their pixel boxes
//    were converted to int unclamped (a segfault in the tile binning);
//  - finding 5: cameras VTK accepts but that define no view (view-up parallel
//    to the view direction, NaN/Inf position or focal point, position = focal
//    point, parallel scale 0, NaN clipping range): status 1 with an error, 0
//    with an error, or a blank window with no message, depending on the mode;
//  - finding 6: an inverted view-depth range and two opposite clipping planes
//    gave an empty image with no message;
//  - finding 4: SetEmissionScale(1e300) (Wilhelms-Van Gelder) gave +Inf pixels.
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

using namespace hovTest;

namespace
{
const double NaN = std::numeric_limits<double>::quiet_NaN();
const double Inf = std::numeric_limits<double>::infinity();

/// Non-finite values in the mapper's float image, and whether it is all zero.
struct FloatStats
{
  size_t NonFinite = 0;
  bool Empty = true;
  size_t Values = 0;
};

FloatStats Stats(vtkHighOrderVolumeMapper* mapper)
{
  FloatStats s;
  auto* a = vtkFloatArray::SafeDownCast(mapper->GetFloatImage()->GetPointData()->GetScalars());
  if (!a)
  {
    return s;
  }
  s.Values = static_cast<size_t>(a->GetNumberOfValues());
  const float* v = a->GetPointer(0);
  for (size_t i = 0; i < s.Values; ++i)
  {
    s.NonFinite += !std::isfinite(v[i]);
    s.Empty = s.Empty && v[i] == 0.0f;
  }
  return s;
}

/// The camera of the axis view, then @p change applied.
struct CameraCase
{
  std::string Name;
  std::function<void(vtkCamera*)> Change;
};

void AxisView(vtkCamera* cam)
{
  cam->SetParallelProjection(0);
  cam->SetFocalPoint(0.5, 0.5, 0.5);
  cam->SetPosition(0.6, 0.7, 4.0);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(30);
  cam->SetClippingRange(0.5, 10.0);
}

/// Checks of one render: status / messages / image, against what the rule says.
struct Expect
{
  bool Error = false;        ///< an error and status 0 (RenderImage)
  bool EmptyWarning = false; ///< status 1, an empty image and a warning
};

void CheckRenderImage(Checker& ck, VolumeScene& scene, vtkCamera* cam, int mode,
  const std::string& what, const Expect& expect)
{
  scene.Mapper->SetRenderMode(mode);
  scene.Observer->Clear();
  int status = -1;
  Render(scene.Mapper, cam, scene.Volume, 32, 24, &status);
  const FloatStats s = Stats(scene.Mapper);
  const std::string tag = std::string(ModeName(mode)) + " RenderImage, " + what;
  ck.Check(s.NonFinite == 0 && s.Values == 32 * 24 * 4, tag + ": finite image of the right size");
  if (expect.Error)
  {
    ck.Check(status == 0 && scene.Observer->GetError(),
      tag + ": status 0 with an error (status " + std::to_string(status) + "): " +
        Msg(scene.Observer->GetErrorMessage()));
  }
  else
  {
    ck.Check(status == 1 && !scene.Observer->GetError(),
      tag + ": status 1, no error (status " + std::to_string(status) + ")");
    ck.Check(!s.Empty || scene.Observer->GetWarning(),
      tag + ": an empty image has a warning: " + Msg(scene.Observer->GetWarningMessage()));
    if (expect.EmptyWarning)
    {
      ck.Check(s.Empty && scene.Observer->GetWarningMessage().find("empty") != std::string::npos,
        tag + ": empty, with a warning saying so");
    }
  }
}

void CheckWindow(Checker& ck, VolumeScene& scene, vtkRenderWindow* win, int mode,
  const std::string& what, const Expect& expect)
{
  scene.Mapper->SetRenderMode(mode);
  scene.Observer->Clear();
  win->Render();
  const FloatStats s = Stats(scene.Mapper);
  const std::string tag = std::string(ModeName(mode)) + " window, " + what;
  ck.Check(s.NonFinite == 0, tag + ": finite float image");
  if (expect.Error)
  {
    ck.Check(scene.Observer->GetError(), tag + ": an error: " + Msg(scene.Observer->GetErrorMessage()));
  }
  else
  {
    ck.Check(!scene.Observer->GetError(), tag + ": no error");
    ck.Check(!s.Empty || scene.Observer->GetWarning(),
      tag + ": an empty image has a warning: " + Msg(scene.Observer->GetWarningMessage()));
  }
}

const int Modes[3] = { vtkHighOrderVolumeMapper::CPU_ACCURATE,
  vtkHighOrderVolumeMapper::OPENGL_PROJECTION, vtkHighOrderVolumeMapper::RAY_CAST };
}

int TestBadInputCameras(int, char*[])
{
  Checker ck;
  VolumeScene scene(UnitBlock(3).Grid());
  DefaultTF(scene.Tf, 0.5);
  vtkNew<vtkCamera> cam;
  auto ren = BlackRenderer(cam);
  auto win = OffscreenWindow(ren, 32, 24);
  ren->AddVolume(scene.Volume);

  // ---- Finding 2: view angle 0 (1e-8 degrees after VTK's clamp), 12 views.
  for (int k = 0; k < 12; ++k)
  {
    AxisView(cam);
    cam->SetPosition(0.5 + 3.0 * ((k % 3) - 1) + 0.01 * k, 0.5 + 2.0 * ((k / 3 % 2) - 0.5),
      k < 6 ? 4.0 : -4.0);
    cam->SetViewAngle(0.0);
    if (k % 4 == 3)
    {
      cam->SetClippingRange(1e-3, 1e6);
    }
    const std::string what = "view angle 0, view " + std::to_string(k);
    for (int mode : Modes)
    {
      CheckRenderImage(ck, scene, cam, mode, what, Expect());
      if (mode != vtkHighOrderVolumeMapper::RAY_CAST || k % 4 == 0)
      {
        CheckWindow(ck, scene, win, mode, what, Expect());
      }
    }
  }

  // ---- Finding 5: cameras that define no view: an error in every mode.
  const std::vector<CameraCase> invalid = {
    { "view-up parallel to the view direction", [](vtkCamera* c) { c->SetViewUp(0.1, 0.2, 3.5); } },
    { "NaN focal point", [](vtkCamera* c) { c->SetFocalPoint(NaN, 0.5, 0.5); } },
    { "Inf position", [](vtkCamera* c) { c->SetPosition(0.5, Inf, 4.0); } },
    { "NaN position", [](vtkCamera* c) { c->SetPosition(NaN, NaN, NaN); } },
    { "NaN view-up", [](vtkCamera* c) { c->SetViewUp(0, NaN, 0); } },
    { "parallel scale 0",
      [](vtkCamera* c) {
        c->SetParallelProjection(1);
        c->SetParallelScale(0.0);
      } },
    { "NaN clipping range", [](vtkCamera* c) { c->SetClippingRange(NaN, 10.0); } },
    // VTK leaves these degenerate: direction of projection (0, 0, 0); near 0.
    { "position = focal point", [](vtkCamera* c) { c->SetPosition(0.5, 0.5, 0.5); } },
    { "zero clipping range", [](vtkCamera* c) { c->SetClippingRange(0.0, 0.0); } },
  };
  for (const CameraCase& cc : invalid)
  {
    AxisView(cam);
    cc.Change(cam);
    Expect error;
    error.Error = true;
    for (int mode : Modes)
    {
      CheckRenderImage(ck, scene, cam, mode, cc.Name, error);
      CheckWindow(ck, scene, win, mode, cc.Name, error);
    }
  }
  // ---- Finding 6: empty slabs are right, silence isn't.
  AxisView(cam);
  Expect empty;
  empty.EmptyWarning = true;
  scene.Mapper->ViewDepthClippingOn();
  scene.Mapper->SetViewDepthRange(3.5, 2.5); // inverted
  for (int mode : { vtkHighOrderVolumeMapper::CPU_ACCURATE, vtkHighOrderVolumeMapper::RAY_CAST })
  {
    CheckRenderImage(ck, scene, cam, mode, "inverted view-depth range", empty);
  }
  scene.Mapper->SetViewDepthRange(NaN, 3.0);
  Expect error;
  error.Error = true;
  for (int mode : Modes)
  {
    CheckRenderImage(ck, scene, cam, mode, "NaN view-depth range", error);
  }
  scene.Mapper->ViewDepthClippingOff();
  vtkNew<vtkPlane> keepLeft, keepRight;
  keepLeft->SetOrigin(0.4, 0, 0);
  keepLeft->SetNormal(-1, 0, 0); // keeps x < 0.4
  keepRight->SetOrigin(0.6, 0, 0);
  keepRight->SetNormal(1, 0, 0); // keeps x > 0.6
  scene.Mapper->AddClippingPlane(keepLeft);
  scene.Mapper->AddClippingPlane(keepRight);
  for (int mode : { vtkHighOrderVolumeMapper::CPU_ACCURATE, vtkHighOrderVolumeMapper::RAY_CAST })
  {
    CheckRenderImage(ck, scene, cam, mode, "opposite clipping planes", empty);
  }
  scene.Mapper->RemoveAllClippingPlanes();
  // Planes that define no half-space (a zero normal; a NaN normal; an Inf
  // origin): left out with a warning, so the image is the unclipped one (a
  // NaN plane used to keep every ray's bounds silently, a zero normal to clip
  // nothing without a word).
  for (int mode : { vtkHighOrderVolumeMapper::CPU_ACCURATE, vtkHighOrderVolumeMapper::RAY_CAST })
  {
    AxisView(cam);
    scene.Mapper->SetRenderMode(mode);
    const Image unclipped = Render(scene.Mapper, cam, scene.Volume, 32, 24);
    vtkNew<vtkPlane> zero, nanNormal, infOrigin;
    zero->SetOrigin(0.5, 0.5, 0.5);
    zero->SetNormal(0, 0, 0);
    nanNormal->SetNormal(NaN, 1, 0);
    infOrigin->SetOrigin(Inf, 0, 0);
    infOrigin->SetNormal(1, 0, 0);
    scene.Mapper->AddClippingPlane(zero);
    scene.Mapper->AddClippingPlane(nanNormal);
    scene.Mapper->AddClippingPlane(infOrigin);
    scene.Observer->Clear();
    int status = -1;
    const Image img = Render(scene.Mapper, cam, scene.Volume, 32, 24, &status);
    const DiffStats d = Diff(img, unclipped);
    const std::string tag = std::string(ModeName(mode)) + " degenerate clipping planes";
    std::cout << tag << ": status " << status << ", vs unclipped " << d.Str() << ", warning '"
              << Msg(scene.Observer->GetWarningMessage()) << "'" << std::endl;
    ck.Check(status == 1 && !scene.Observer->GetError() && d.Max == 0.0 &&
        CheckImage(img).Covered > 0,
      tag + ": the unclipped image");
    ck.Check(scene.Observer->GetWarningMessage().find("3 clipping plane(s)") != std::string::npos,
      tag + ": a warning counts the 3 planes ignored");
    scene.Mapper->RemoveAllClippingPlanes();
  }

  // ---- Finding 4: an absurd emission scale is clamped (with a warning); an
  // emission that still overflows (a unit distance of 1e-300) gives
  // transparent pixels and a warning, never Inf.
  scene.Mapper->SetEmissionModelToWilhelmsVanGelder();
  scene.Observer->Clear();
  scene.Mapper->SetEmissionScale(1e300);
  ck.Check(scene.Mapper->GetEmissionScale() == 1e6 && scene.Observer->GetWarning(),
    "SetEmissionScale(1e300) clamped to 1e6 with a warning: " +
      Msg(scene.Observer->GetWarningMessage()));
  scene.Observer->Clear();
  scene.Mapper->SetEmissionScale(NaN);
  ck.Check(scene.Mapper->GetEmissionScale() == 1e6 && scene.Observer->GetError(),
    "SetEmissionScale(NaN) refused with an error");
  for (int mode : Modes)
  {
    CheckRenderImage(ck, scene, cam, mode, "emission scale 1e6", Expect());
    CheckWindow(ck, scene, win, mode, "emission scale 1e6", Expect());
  }
  // Glow beyond float's range: colour 1e37 x scale 1e6 per unit length.
  scene.Tf.Color->RemoveAllPoints();
  scene.Tf.Color->AddRGBPoint(0.0, 1e37, 1.0, 1.0);
  scene.Tf.Opacity->RemoveAllPoints();
  scene.Tf.Opacity->AddPoint(0.0, 0.01);
  for (int mode : Modes)
  {
    scene.Mapper->SetRenderMode(mode);
    scene.Observer->Clear();
    int status = -1;
    Render(scene.Mapper, cam, scene.Volume, 32, 24, &status);
    FloatStats s = Stats(scene.Mapper);
    std::string tag = std::string(ModeName(mode)) + ", glow beyond float's range";
    ck.Check(status == 1 && s.NonFinite == 0, tag + ": status 1 and a finite image");
    ck.Check(scene.Observer->GetWarningMessage().find("not finite or beyond") != std::string::npos,
      tag + ": the overflowing pixels are reported: " + Msg(scene.Observer->GetWarningMessage()));
    scene.Observer->Clear();
    win->Render();
    s = Stats(scene.Mapper);
    tag = std::string(ModeName(mode)) + " window, glow beyond float's range";
    ck.Check(s.NonFinite == 0, tag + ": a finite float image");
    // OPENGL_PROJECTION's vertex colours overflow before any pixel does.
    const std::string expected = mode == vtkHighOrderVolumeMapper::OPENGL_PROJECTION
      ? "computes in float"
      : "not finite or beyond";
    ck.Check(scene.Observer->GetWarningMessage().find(expected) != std::string::npos,
      tag + ": the overflow is reported: " + Msg(scene.Observer->GetWarningMessage()));
  }
  scene.Mapper->SetEmissionScale(1.0);
  scene.Mapper->SetEmissionModelToWilliamsMax();
  return ck.Result();
}
