// The CPU path's pixel rays, a row of four pixels per vector where nothing
// clips them, are the per-pixel rays bit for bit: the double image
// (GetDoubleImage) of the bundled bracket in a perspective and in a parallel
// view is the same, value for value, with and without a clipping plane that
// cuts nothing (the rays of a clipped view are traced one pixel at a time, and
// such a plane leaves every ray as it is). 203 x 157 pixels: tiles whose
// width is not a multiple of four.
#include "hovTestImages.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkPlane.h"

#include <string>

using namespace hovTest;

int TestPixelRays(int argc, char* argv[])
{
  Checker ck;
  std::unique_ptr<VolumeScene> scene = BracketScene(ck, argc, argv);
  if (!scene)
  {
    return ck.Result();
  }
  vtkHighOrderVolumeMapper* mapper = scene->Mapper;
  mapper->SetRenderModeToCPUAccurate();
  // A plane far outside the data, keeping all of it (and every ray).
  vtkNew<vtkPlane> far;
  far->SetOrigin(0.0, 0.0, -1e4);
  far->SetNormal(0.0, 0.0, 1.0);
  for (const bool parallel : { false, true })
  {
    const std::string view = parallel ? "parallel view" : "perspective view";
    vtkNew<vtkCamera> camera;
    BracketCamera(camera);
    camera->SetParallelProjection(parallel);
    camera->SetParallelScale(60.0);
    mapper->RemoveAllClippingPlanes();
    int status[2] = { 0, 0 };
    Render(mapper, camera, scene->Volume, 203, 157, &status[0]);
    const Image rows = DoubleImage(mapper);
    mapper->AddClippingPlane(far);
    Render(mapper, camera, scene->Volume, 203, 157, &status[1]);
    const Image pixels = DoubleImage(mapper);
    const Sanity sane = CheckImage(rows);
    ck.Check(status[0] == 1 && status[1] == 1 && rows.V.size() == pixels.V.size() &&
        sane.Covered > 5000,
      view + ": both images rendered, " + std::to_string(sane.Covered) + " covered pixels");
    size_t differ = 0;
    for (size_t i = 0; i < rows.V.size() && rows.V.size() == pixels.V.size(); ++i)
    {
      differ += rows.V[i] != pixels.V[i];
    }
    ck.Check(differ == 0,
      view + ": row rays == per-pixel rays, bit for bit (" + std::to_string(differ) +
        " values differ)");
  }
  mapper->RemoveAllClippingPlanes();
  ck.Check(scene->NoMessages(), "no messages");
  return ck.Result();
}
