// OpenGL state is not leaked, in every render mode (CPU_ACCURATE, whose image
// is blitted over the scene; OPENGL_PROJECTION, which draws into a float
// target and composites it; RAY_CAST). A scene of two overlapping opaque boxes (the
// farther one added last, so a leaked disabled depth test would draw it on
// top), a translucent box and a translucent 2D overlay (both sensitive to a
// leaked blend function) is rendered without and with the volume. At every
// pixel the volume does not cover (float RGBA exactly 0) the frames with the
// volume must equal the frame without it exactly, frame after frame; removing
// the volume again restores the original frame exactly. Then render ->
// mapper->ReleaseGraphicsResources(win) -> render gives identical screen and
// float images.
#include "hovTestScenes.h"

#include "vtkActor.h"
#include "vtkActor2D.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCoordinate.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper2D.h"
#include "vtkProperty2D.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace hovTest;

namespace
{
/// Pixels (and max difference) where two screen images differ, restricted to
/// pixels whose float RGBA is exactly zero (if @p fl is given).
size_t CountDiff(const Image& a, const Image& b, const Image* fl, size_t& considered, double& maxd)
{
  size_t n = 0;
  considered = 0;
  maxd = 0;
  for (int j = 0; j < a.H; ++j)
  {
    for (int i = 0; i < a.W; ++i)
    {
      if (fl && (fl->At(i, j, 0) != 0 || fl->At(i, j, 1) != 0 || fl->At(i, j, 2) != 0 ||
                  fl->At(i, j, 3) != 0))
      {
        continue;
      }
      ++considered;
      bool differ = false;
      for (int c = 0; c < 3; ++c)
      {
        const double d = std::abs(a.At(i, j, c) - b.At(i, j, c));
        maxd = std::max(maxd, d);
        differ = differ || d != 0;
      }
      n += differ;
    }
  }
  return n;
}

/// The test in render mode @p mode (checks named with @p name).
void CheckMode(Checker& ck, int mode, const std::string& name)
{
  std::cout << "==== " << name << "\n";
  VolumeScene scene(UnitBlock(2).Grid());
  DefaultTF(scene.Tf);
  scene.Mapper->SetRenderMode(mode);
  if (mode == vtkHighOrderVolumeMapper::OPENGL_PROJECTION)
  {
    scene.Mapper->SetOpacitySemanticsToVTKUnstructured();
  }

  auto check = [&](bool ok, const std::string& what) { ck.Check(ok, name + ": " + what); };
  vtkNew<vtkCamera> cam;
  cam->SetFocalPoint(1.0, 0.5, 0.5);
  cam->SetPosition(1.6, 1.3, 4.5);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(40);
  cam->SetClippingRange(0.5, 20);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0.1, 0.15, 0.2);
  ren->SetActiveCamera(cam);
  vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(ren, 220, 160, 0);

  // Geometry to the right of the volume (x > 1.2), overlapping on screen.
  const double red[3] = { 0.9, 0.1, 0.1 }, blue[3] = { 0.1, 0.2, 0.9 },
               green[3] = { 0.2, 0.9, 0.3 };
  const double nearBox[6] = { 1.3, 1.8, 0.1, 0.6, 0.8, 1.2 };
  const double farBox[6] = { 1.5, 2.1, 0.3, 1.0, -0.6, -0.2 };
  const double glassBox[6] = { 1.25, 1.9, 0.5, 1.2, 0.2, 0.5 };
  ren->AddActor(BoxActor(nearBox, red));
  ren->AddActor(BoxActor(farBox, blue)); // drawn after the nearer box
  ren->AddActor(BoxActor(glassBox, green, 0.4));
  // A translucent 2D rectangle in the top-left corner (overlay pass, after volumes).
  vtkNew<vtkPoints> p2;
  p2->InsertNextPoint(5, 110, 0);
  p2->InsertNextPoint(70, 110, 0);
  p2->InsertNextPoint(70, 155, 0);
  p2->InsertNextPoint(5, 155, 0);
  vtkNew<vtkCellArray> q2;
  const vtkIdType quad[4] = { 0, 1, 2, 3 };
  q2->InsertNextCell(4, quad);
  vtkNew<vtkPolyData> rect;
  rect->SetPoints(p2);
  rect->SetPolys(q2);
  vtkNew<vtkPolyDataMapper2D> m2;
  m2->SetInputData(rect);
  vtkNew<vtkActor2D> overlay;
  overlay->SetMapper(m2);
  overlay->GetProperty()->SetColor(1.0, 0.9, 0.1);
  overlay->GetProperty()->SetOpacity(0.5);
  ren->AddActor2D(overlay);

  win->Render();
  const Image a1 = Capture(win);
  win->Render();
  const Image a1b = Capture(win);
  size_t considered;
  double maxd;
  const size_t selfDiff = CountDiff(a1, a1b, nullptr, considered, maxd);
  std::cout << "== scene without the volume rendered twice: " << selfDiff << " pixels differ\n";
  check(selfDiff == 0, "(the scene alone is deterministic)");

  ren->AddVolume(scene.Volume);
  scene.Observer->Clear();
  Image fl;
  std::vector<Image> frames;
  for (int f = 0; f < 3; ++f)
  {
    win->Render();
    frames.push_back(Capture(win));
    fl = FloatImage(scene.Mapper);
  }
  const Sanity s = CheckImage(fl);
  std::cout << "== with the volume: " << s.Str() << "\n";
  check(scene.NoMessages(), "no messages");
  check(s.Ok() && s.Covered > 2000, "the volume is drawn");
  for (int f = 0; f < 3; ++f)
  {
    const size_t n = CountDiff(frames[f], a1, &fl, considered, maxd);
    std::cout << "  frame " << f + 1 << " vs no volume, at the " << considered
              << " pixels the volume does not cover: " << n << " differ (max " << maxd * 255
              << "/255)\n";
    check(considered > 10000 && n == 0,
      "frame " + std::to_string(f + 1) + ": uncovered pixels equal the scene without the volume");
  }
  size_t n = CountDiff(frames[1], frames[2], nullptr, considered, maxd);
  std::cout << "  frame 2 vs frame 3 (all pixels): " << n << " differ\n";
  check(n == 0, "consecutive frames with the volume are identical");
  // Covered pixels do change (the test can see the volume).
  size_t covered = 0, changed = 0;
  for (int j = 0; j < fl.H; ++j)
  {
    for (int i = 0; i < fl.W; ++i)
    {
      if (fl.At(i, j, 3) > 0.05)
      {
        ++covered;
        changed += frames[2].At(i, j, 0) != a1.At(i, j, 0) || frames[2].At(i, j, 1) != a1.At(i, j, 1) ||
          frames[2].At(i, j, 2) != a1.At(i, j, 2);
      }
    }
  }
  std::cout << "  pixels with alpha > 0.05: " << covered << ", of which changed on screen: "
            << changed << "\n";
  check(covered > 1000 && changed > 0.95 * covered, "covered pixels show the volume");

  ren->RemoveVolume(scene.Volume);
  win->Render();
  n = CountDiff(Capture(win), a1, nullptr, considered, maxd);
  std::cout << "== volume removed again: " << n << " pixels differ from the original frame\n";
  check(n == 0, "removing the volume restores the original frame exactly");

  // Render -> ReleaseGraphicsResources -> render.
  ren->AddVolume(scene.Volume);
  win->Render();
  const Image r1 = Capture(win);
  const Image f1 = FloatImage(scene.Mapper);
  scene.Mapper->ReleaseGraphicsResources(win);
  win->Render();
  const Image r2 = Capture(win);
  const Image f2 = FloatImage(scene.Mapper);
  n = CountDiff(r1, r2, nullptr, considered, maxd);
  const DiffStats fd = Diff(f1, f2);
  std::cout << "== render / ReleaseGraphicsResources / render: screen pixels differing " << n
            << " (max " << maxd * 255 << "/255), float " << fd.Str() << "\n";
  check(n == 0 && fd.Max == 0.0, "identical screen and float images after releasing resources");
  // Twice in a row, and once more after the window's own release.
  scene.Mapper->ReleaseGraphicsResources(win);
  scene.Mapper->ReleaseGraphicsResources(win);
  win->Render();
  n = CountDiff(r1, Capture(win), nullptr, considered, maxd);
  std::cout << "  after two releases in a row: " << n << " pixels differ\n";
  check(n == 0, "identical after releasing twice");
  check(scene.NoMessages(), "no messages");
  scene.Mapper->ReleaseGraphicsResources(win);
}
}

int TestOpenGLState(int, char*[])
{
  Checker ck;
  CheckMode(ck, vtkHighOrderVolumeMapper::CPU_ACCURATE, "CPU_ACCURATE");
  CheckMode(ck, vtkHighOrderVolumeMapper::OPENGL_PROJECTION, "OPENGL_PROJECTION");
  CheckMode(ck, vtkHighOrderVolumeMapper::RAY_CAST, "RAY_CAST");
  return ck.Result();
}
