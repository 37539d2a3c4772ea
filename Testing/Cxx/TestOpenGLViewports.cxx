// Several renderers (viewports) in one window.
//
// (1) 2x2 grid, 300x200 window. Bottom-left: an opaque box filling the view
// right in front of the camera (depth ~0 everywhere); bottom-right and
// top-left: other backgrounds and a box; top-right (x0 = 150, y0 = 100): the
// volume (unit cube, orthographic axis view, constant transfer function) and
// an opaque plate cutting it at z = 0.55. The float image must be 150x100;
// the top-right quadrant must be the float image over the scene without the
// volume (within 1.5/255), the three other quadrants must be untouched
// (exactly), and the plate must clip the volume exactly as analysed in
// TestOpenGLDepth (so the depth is read from the right viewport, not from the
// bottom-left one).
// (2) The same volume in two side-by-side renderers with different cameras:
// each half of the screen equals RenderImage for that camera and viewport
// size within 1.5/255.
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <iostream>

using namespace hovTest;

int TestOpenGLViewports(int, char*[])
{
  Checker ck;
  VolumeScene scene(UnitBlock(2).Grid());
  const double a = 0.5, u = 0.5, orange[3] = { 0.9, 0.6, 0.3 };
  ConstantTF(scene.Tf, orange, a, u);

  // ---- (1) 2x2 grid.
  {
    const int W = 300, H = 200, w = 150, h = 100;
    vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(nullptr, W, H, 0);
    const double green[3] = { 0.1, 0.7, 0.2 }, grey[3] = { 0.5, 0.5, 0.5 };

    vtkNew<vtkRenderer> bl, br, tl, tr;
    bl->SetViewport(0, 0, 0.5, 0.5);
    br->SetViewport(0.5, 0, 1, 0.5);
    tl->SetViewport(0, 0.5, 0.5, 1);
    tr->SetViewport(0.5, 0.5, 1, 1);
    bl->SetBackground(0.3, 0, 0);
    br->SetBackground(0, 0.3, 0);
    tl->SetBackground(0, 0, 0.3);
    tr->SetBackground(0, 0, 0);
    // Bottom-left: a wall just past the near plane, covering the viewport.
    vtkNew<vtkCamera> blCam;
    AxisOrthoCamera(blCam, 1.0, AxisOrthoShift);
    bl->SetActiveCamera(blCam);
    const double wall[6] = { -5, 6, -5, 6, 3.8, 3.9 };
    bl->AddActor(BoxActor(wall, grey));
    // Bottom-right: a box.
    vtkNew<vtkCamera> brCam;
    ObliqueCamera(brCam);
    br->SetActiveCamera(brCam);
    const double boxB[6] = { 0.2, 0.8, 0.2, 0.8, 0.2, 0.8 };
    br->AddActor(BoxActor(boxB, grey));
    // Top-right: volume + cutting plate; orthographic, aspect 1.5.
    vtkNew<vtkCamera> trCam;
    AxisOrthoCamera(trCam, 1.0, AxisOrthoShift);
    tr->SetActiveCamera(trCam);
    const double plateM[6] = { 0.40, 0.60, -0.3, 1.3, 0.45, 0.55 };
    tr->AddActor(BoxActor(plateM, green));
    for (vtkRenderer* r : { bl.Get(), br.Get(), tl.Get(), tr.Get() })
    {
      win->AddRenderer(r);
    }

    win->Render();
    const Image without = Capture(win);
    tr->AddVolume(scene.Volume);
    scene.Observer->Clear();
    win->Render();
    const Image with = Capture(win);
    const Image fl = FloatImage(scene.Mapper);
    std::cout << "== 2x2 viewports " << W << "x" << H << ": float image " << fl.W << "x" << fl.H
              << " (expected " << w << "x" << h << ") " << CheckImage(fl).Str() << "\n";
    ck.Check(scene.NoMessages(), "no messages");
    ck.Check(fl.W == w && fl.H == h, "the float image has the top-right viewport's size");
    if (fl.W == w && fl.H == h)
    {
      // Top-right: float over the scene without the volume.
      double blendErr = 0;
      for (int j = 0; j < h; ++j)
      {
        for (int i = 0; i < w; ++i)
        {
          for (int c = 0; c < 3; ++c)
          {
            const double expect = fl.At(i, j, c) + (1 - fl.At(i, j, 3)) * without.At(w + i, h + j, c);
            blendErr = std::max(blendErr, std::abs(with.At(w + i, h + j, c) - expect));
          }
        }
      }
      // Other quadrants untouched.
      size_t touched = 0;
      for (int j = 0; j < H; ++j)
      {
        for (int i = 0; i < W; ++i)
        {
          if (i >= w && j >= h)
          {
            continue;
          }
          for (int c = 0; c < 3; ++c)
          {
            touched += with.At(i, j, c) != without.At(i, j, c);
          }
        }
      }
      // Depth clipping in the viewport: analytic alphas (aspect 1.5).
      const double alphaFull = 1.0 - std::pow(1.0 - a, 1.0 / u);
      const double alphaCut = 1.0 - std::pow(1.0 - a, 0.45 / u);
      const double margin = 1.5 * 2.0 / h;
      double errFull = 0, errCut = 0, errOut = 0;
      size_t nFull = 0, nCut = 0, nOut = 0;
      for (int j = 0; j < h; ++j)
      {
        const double y = OrthoPixelCoord(j, h);
        for (int i = 0; i < w; ++i)
        {
          const double x = OrthoPixelCoord(i, w, 1.0, double(w) / h, AxisOrthoShift);
          const double al = fl.At(i, j, 3);
          const bool inCube = x > margin && x < 1 - margin && y > margin && y < 1 - margin;
          const bool outCube = x < -margin || x > 1 + margin || y < -margin || y > 1 + margin;
          if (inCube && x > plateM[0] + margin && x < plateM[1] - margin)
          {
            ++nCut;
            errCut = std::max(errCut, std::abs(al - alphaCut));
          }
          else if (inCube && (x < plateM[0] - margin || x > plateM[1] + margin))
          {
            ++nFull;
            errFull = std::max(errFull, std::abs(al - alphaFull));
          }
          else if (outCube)
          {
            ++nOut;
            errOut = std::max(errOut, std::abs(al));
          }
        }
      }
      std::cout << "  top-right: screen vs float over the scene: max " << blendErr * 255
                << "/255\n  other quadrants: " << touched << " channel values changed\n"
                << "  cube pixels without plate: " << nFull << ", max |alpha - " << alphaFull
                << "| = " << errFull << "\n  cube pixels under the plate: " << nCut
                << ", max |alpha - " << alphaCut << "| = " << errCut
                << "\n  pixels outside the cube: " << nOut << ", max alpha " << errOut << "\n";
      ck.Check(blendErr <= 1.5 / 255, "top-right quadrant = float over the scene within 1.5/255");
      ck.Check(touched == 0, "the other viewports are untouched");
      ck.Check(nFull > 1000 && errFull <= 1e-6, "unclipped rays: analytic alpha");
      ck.Check(nCut > 100 && errCut <= 1e-4,
        "the plate in the same viewport clips at z = 0.55 (depth read from the right viewport)");
      ck.Check(nOut > 1000 && errOut == 0, "nothing outside the cube's footprint");
    }
    scene.Mapper->ReleaseGraphicsResources(win);
  }

  // ---- (2) One volume, two renderers, two cameras.
  {
    const int W = 320, H = 200, w = 160;
    vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(nullptr, W, H, 0);
    vtkNew<vtkRenderer> left, right;
    left->SetViewport(0, 0, 0.5, 1);
    right->SetViewport(0.5, 0, 1, 1);
    left->SetBackground(0, 0, 0);
    right->SetBackground(0, 0, 0);
    vtkNew<vtkCamera> lc, rc;
    ObliqueCamera(lc);
    AxisOrthoCamera(rc, 0.8, AxisOrthoShift);
    left->SetActiveCamera(lc);
    right->SetActiveCamera(rc);
    left->AddVolume(scene.Volume);
    right->AddVolume(scene.Volume);
    win->AddRenderer(left);
    win->AddRenderer(right);
    scene.Observer->Clear();
    win->Render();
    const Image screen = Capture(win);
    ck.Check(scene.NoMessages(), "no messages");
    scene.Mapper->RenderImage(lc, scene.Volume, w, H);
    const Image fl = FloatImage(scene.Mapper);
    scene.Mapper->RenderImage(rc, scene.Volume, w, H);
    const Image fr = FloatImage(scene.Mapper);
    Image sl = Crop(screen, 0, 0, w, H), sr = Crop(screen, w, 0, w, H);
    const DiffStats dl = Diff(sl, fl, 0, 3, 1.5 / 255), dr = Diff(sr, fr, 0, 3, 1.5 / 255);
    // Swapped halves must not match (the test sees which view is where).
    const DiffStats swapped = Diff(sl, fr, 0, 3, 1.5 / 255);
    std::cout << "== one volume in two viewports " << W << "x" << H << "\n  left  (oblique) vs RenderImage: max "
              << dl.Max * 255 << "/255 mean " << dl.Mean * 255 << "/255\n  right (axis)    vs RenderImage: max "
              << dr.Max * 255 << "/255 mean " << dr.Mean * 255 << "/255\n  left vs the right camera's image: max "
              << swapped.Max * 255 << "/255\n  left float alpha mean " << MeanChannel(fl, 3)
              << ", right " << MeanChannel(fr, 3) << "\n";
    ck.Check(MeanChannel(fl, 3) > 0.05 && MeanChannel(fr, 3) > 0.05, "both views show the volume");
    ck.Check(dl.Max <= 1.5 / 255, "left viewport = RenderImage(left camera, 160x200) within 1.5/255");
    ck.Check(dr.Max <= 1.5 / 255, "right viewport = RenderImage(right camera, 160x200) within 1.5/255");
    ck.Check(swapped.Max > 0.1, "(the two views differ)");
    scene.Mapper->ReleaseGraphicsResources(win);
  }
  return ck.Result();
}
