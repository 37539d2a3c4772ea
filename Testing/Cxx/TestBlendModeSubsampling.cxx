// Blend modes (MIP, MinIP, average intensity) in reduced interactive frames:
// the bracket in a 160 x 120 window, InteractiveSubsampling 4 and a desired
// update rate of 1e5 (an interactive frame, 4 x 4 pixels per ray), in
// CPU_ACCURATE and OPENGL_PROJECTION (which draws blend modes with the CPU
// projector). The interactive frame must be the image of the 40 x 30 rays
// (RenderImage at 40 x 30, the same aspect) with each value repeated over its
// 4 x 4 block: within 1e-6 everywhere, and covering what the full frame
// covers. (Before the fix the reduced image was published as if it were
// full-size: a few rows of garbled pixels.)
#include "hovTestImages.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <string>

using namespace hovTest;

int TestBlendModeSubsampling(int argc, char* argv[])
{
  Checker ck;
  std::unique_ptr<VolumeScene> scene = BracketScene(ck, argc, argv);
  if (!scene)
  {
    return ck.Result();
  }
  vtkHighOrderVolumeMapper* mapper = scene->Mapper;
  constexpr int W = 160, H = 120, F = 4;
  vtkNew<vtkCamera> cam;
  BracketCamera(cam);
  vtkSmartPointer<vtkRenderer> ren = BlackRenderer(cam);
  ren->AddVolume(scene->Volume);
  vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(ren, W, H, 0);
  struct Blend
  {
    const char* Name;
    int Mode;
  };
  // vtkVolumeMapper's MAXIMUM_INTENSITY_BLEND, MINIMUM_INTENSITY_BLEND, AVERAGE_INTENSITY_BLEND.
  const Blend blends[] = { { "MIP", 1 }, { "MinIP", 2 }, { "average", 3 } };
  for (int mode : { vtkHighOrderVolumeMapper::CPU_ACCURATE,
         vtkHighOrderVolumeMapper::OPENGL_PROJECTION })
  {
    mapper->SetRenderMode(mode);
    for (const Blend& b : blends)
    {
      const bool cpu = mode == vtkHighOrderVolumeMapper::CPU_ACCURATE;
      const std::string name = std::string(cpu ? "CPU_ACCURATE " : "OPENGL_PROJECTION ") + b.Name;
      mapper->SetBlendMode(b.Mode);
      const Image reduced = Render(mapper, cam, scene->Volume, W / F, H / F);
      mapper->SetInteractiveSubsampling(0);
      mapper->AutoAdjustImageSampleDistanceOff();
      win->SetDesiredUpdateRate(0.0001);
      win->Render();
      const Image full = FloatImage(mapper);
      mapper->AutoAdjustImageSampleDistanceOn();
      mapper->SetInteractiveSubsampling(F);
      win->SetDesiredUpdateRate(1e5);
      win->Render();
      const Image frame = FloatImage(mapper);
      win->SetDesiredUpdateRate(0.0001);
      ck.Check(mapper->GetLastRenderWasInteractive() && mapper->GetLastSubsampling() == F,
        name + ": an interactive frame at " + std::to_string(F) + " x " + std::to_string(F) +
          " pixels per ray (got " + std::to_string(mapper->GetLastSubsampling()) + ")");
      double worst = frame.W == W && reduced.W == W / F ? 0.0 : 1e300;
      size_t coveredFull = 0, coveredFrame = 0;
      for (int j = 0; j < H && worst < 1e300; ++j)
      {
        for (int i = 0; i < W; ++i)
        {
          for (int c = 0; c < 4; ++c)
          {
            worst = std::max(worst, std::abs(frame.At(i, j, c) - reduced.At(i / F, j / F, c)));
          }
          coveredFull += full.At(i, j, 3) > 0.0;
          coveredFrame += frame.At(i, j, 3) > 0.0;
        }
      }
      ck.Check(worst <= 1e-6,
        name + ": the interactive frame is the 40 x 30 image expanded (max difference " +
          Fmt(worst) + ")");
      ck.Check(coveredFull > 2000 &&
          std::abs(static_cast<double>(coveredFrame) - static_cast<double>(coveredFull)) <
            0.2 * coveredFull,
        name + ": it covers what the full frame covers (" + std::to_string(coveredFrame) +
          " vs " + std::to_string(coveredFull) + " pixels)");
    }
  }
  mapper->SetInteractiveSubsampling(0);
  ck.Check(scene->NoMessages(), "no messages");
  return ck.Result();
}
