// On screen (offscreen window under Xvfb), black background, volume only:
// the framebuffer equals the float image (premultiplied, so screen RGB =
// float RGB) within 1.5/255 per channel; the on-screen float image equals
// RenderImage's for the same camera and size; after a window resize (odd
// sizes) both follow the new size.
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <iostream>

using namespace hovTest;

namespace
{
/// Screen RGB vs float RGB (and alpha if the window has alpha planes).
DiffStats ScreenVsFloat(const Image& screen, const Image& fl, int c1)
{
  Image s = screen;
  return Diff(s, fl, 0, c1, 1.5 / 255);
}
}

int TestOpenGLScreen(int, char*[])
{
  Checker ck;
  VolumeScene scene(UnitBlock(3).Grid());
  DefaultTF(scene.Tf);

  vtkNew<vtkCamera> cam;
  ObliqueCamera(cam);
  vtkSmartPointer<vtkRenderer> ren = BlackRenderer(cam);
  ren->AddVolume(scene.Volume);
  const int sizes[3][2] = { { 240, 180 }, { 131, 97 }, { 180, 240 } };
  vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(ren, sizes[0][0], sizes[0][1]);
  win->SetAlphaBitPlanes(1);

  for (int semantics : { 0, 1 })
  {
    scene.Mapper->SetOpacitySemantics(semantics);
    for (const auto& sz : sizes)
    {
      win->SetSize(sz[0], sz[1]);
      scene.Observer->Clear();
      win->Render();
      const Image fl = FloatImage(scene.Mapper);
      const Image screen = Capture(win, true);
      const Sanity s = CheckImage(fl);
      std::cout << "== " << (semantics ? "VTK_UNSTRUCTURED" : "GPU_COMPATIBLE") << " window "
                << sz[0] << "x" << sz[1] << ": float " << fl.W << "x" << fl.H << ", screen "
                << screen.W << "x" << screen.H << "; " << s.Str() << "\n";
      ck.Check(scene.NoMessages(), "no messages");
      ck.Check(fl.W == sz[0] && fl.H == sz[1] && screen.W == sz[0] && screen.H == sz[1],
        "float image and screen have the window size");
      ck.Check(s.Ok() && s.Covered > 0.1 * sz[0] * sz[1], "float image is sane and covers > 10%");
      if (fl.W != screen.W || fl.H != screen.H)
      {
        continue;
      }
      const DiffStats rgb = ScreenVsFloat(screen, fl, 3);
      std::cout << "  screen RGB vs float RGB (x255): max " << rgb.Max * 255 << " mean "
                << rgb.Mean * 255 << " p99 " << rgb.P99 * 255 << " pixels > 1.5/255: " << rgb.Above
                << "\n";
      ck.Check(rgb.Max <= 1.5 / 255, "screen RGB = float RGB within 1.5/255");
      // The framebuffer's alpha (cleared to 0) becomes the volume's alpha with
      // the separate alpha blend factors; reported, asserted only if present.
      const DiffStats alpha = Diff(screen, fl, 3, 4, 1.5 / 255);
      std::cout << "  framebuffer alpha planes: " << win->GetAlphaBitPlanes()
                << "; screen alpha vs float alpha (x255): max " << alpha.Max * 255 << " mean "
                << alpha.Mean * 255 << "\n";
      if (win->GetAlphaBitPlanes())
      {
        ck.Check(alpha.Max <= 1.5 / 255, "framebuffer alpha = float alpha within 1.5/255");
      }
      // RenderImage with the same camera and size: the same float image.
      const int st = scene.Mapper->RenderImage(cam, scene.Volume, sz[0], sz[1]);
      const Image offline = FloatImage(scene.Mapper);
      const DiffStats d = Diff(offline, fl);
      std::cout << "  RenderImage vs on-screen float image: " << d.Str() << "\n";
      ck.Check(st == 1 && d.Max <= 1e-7,
        "on-screen float image = RenderImage's for the same camera and size");
    }
  }
  scene.Mapper->ReleaseGraphicsResources(win);
  return ck.Result();
}
