// OPENGL_PROJECTION streams the region triangles group after group into one
// vertex and one index buffer (hov::ProjectionStream; the storage rule,
// within 2.5x the largest group however many groups and frames, is tested on
// its own: hov.Kernels StreamPlacement.*). Here the OpenGL side, through the
// public mapper, in the case that broke it: a transfer function of thousands
// of nodes (ParaView's default colour map, 256 steps in a non-linear colour
// space, gives thousands), which cuts every cell into many slabs, so that a
// frame streams many groups. Regression: the storage doubled at every refill
// and grew to gigabytes: GL_OUT_OF_MEMORY, then GL_INVALID_VALUE from the
// mapping and an empty image, or a crash in llvmpipe. Checks over five frames:
// no error or warning, the volume drawn, and every frame's float image equal
// to the first (the buffers are reused, refilled and regrown correctly).
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <iostream>

using namespace hovTest;

int TestProjectionStream(int, char*[])
{
  Checker ck;
  VolumeScene scene(UnitBlock(4).Grid());
  // 2000 colour nodes over the field's range [0, 1.75]: a sawtooth of hues.
  scene.Tf.Color->RemoveAllPoints();
  for (int k = 0; k <= 2000; ++k)
  {
    const double s = 1.75 * k / 2000.0;
    const double phase = (k % 7) / 6.0;
    scene.Tf.Color->AddRGBPoint(s, phase, 1.0 - phase, 0.5 + 0.5 * std::sin(6.0 * s));
  }
  scene.Tf.Opacity->RemoveAllPoints();
  scene.Tf.Opacity->AddPoint(0.0, 0.2);
  scene.Tf.Opacity->AddPoint(1.75, 0.6);
  scene.Tf.Property->SetScalarOpacityUnitDistance(0.5);
  scene.Mapper->SetRenderModeToOpenGLProjection();
  scene.Mapper->SetOpacitySemanticsToVTKUnstructured();

  vtkNew<vtkCamera> cam;
  ObliqueCamera(cam);
  vtkSmartPointer<vtkRenderer> ren = BlackRenderer(cam);
  ren->AddVolume(scene.Volume);
  vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(ren, 96, 96, 0);
  Image first;
  double worst = 0.0;
  for (int frame = 0; frame < 5; ++frame)
  {
    win->Render();
    const Image image = FloatImage(scene.Mapper);
    if (frame == 0)
    {
      first = image;
      continue;
    }
    worst = std::max(worst, Diff(first, image).Max);
  }
  const Sanity s = CheckImage(first);
  std::cout << "[measured] " << scene.Mapper->GetNumberOfProjectedSlabs() << " slabs, "
            << scene.Mapper->GetNumberOfProjectedTriangles() << " triangles per frame; "
            << s.Str() << "; largest difference from the first frame " << worst << "\n";
  ck.Check(scene.NoMessages(), "no error or warning (OpenGL errors are reported as errors)");
  ck.Check(s.Ok() && s.Covered > 1000, "the volume is drawn");
  ck.Check(scene.Mapper->GetNumberOfProjectedSlabs() > 20 * 384, "many slabs per cell");
  ck.Check(worst == 0.0, "every frame equals the first");
  scene.Mapper->ReleaseGraphicsResources(win);
  return ck.Result();
}
