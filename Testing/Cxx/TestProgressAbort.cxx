// Progress events and abort of the CPU path (hovTileBatches.h) on the
// bundled bracket (56071 tetrahedra), plain path and feature path (an
// isosurface): with a ProgressEvent observer the progress starts at 0, never
// decreases, ends at exactly 1, and the float image is bit-identical to the
// image rendered without an observer (one parallel tile loop); an observer
// that sets AbortExecute at 25% stops the render early (LastRenderAborted,
// last progress < 1, no NaN, every pixel either equal to the full image or
// zero, fewer non-zero pixels); the next render without abort is complete
// and bit-identical again. The same for the RAY_CAST mode (rows of rays in
// batches), and an AbortCheckEvent observer of a render window stops both.
#include "hovTestScenes.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <string>
#include <vector>

using namespace hovTest;

namespace
{
struct ProgressLog
{
  std::vector<double> Values;
  double AbortAt = 2.0; ///< set AbortExecute once progress reaches this
};

void OnProgress(vtkObject* caller, unsigned long, void* clientData, void* callData)
{
  auto* log = static_cast<ProgressLog*>(clientData);
  const double p = *static_cast<double*>(callData);
  log->Values.push_back(p);
  if (p >= log->AbortAt)
  {
    static_cast<vtkHighOrderVolumeMapper*>(caller)->SetAbortExecute(1);
  }
}

size_t NonZero(const Image& img)
{
  size_t n = 0;
  for (size_t p = 0; p < img.Pixels(); ++p)
  {
    n += img.V[4 * p + 3] != 0.0;
  }
  return n;
}

void CheckCase(Checker& ck, VolumeScene& scene, vtkCamera* cam, const std::string& name)
{
  const int w = 160, h = 120;
  vtkHighOrderVolumeMapper* mapper = scene.Mapper;
  const Image plain = Render(mapper, cam, scene.Volume, w, h);

  ProgressLog log;
  vtkNew<vtkCallbackCommand> cb;
  cb->SetCallback(OnProgress);
  cb->SetClientData(&log);
  const unsigned long tag = mapper->AddObserver(vtkCommand::ProgressEvent, cb);
  const Image observed = Render(mapper, cam, scene.Volume, w, h);
  bool monotone = !log.Values.empty() && log.Values.front() == 0.0;
  for (size_t i = 1; i < log.Values.size(); ++i)
  {
    monotone = monotone && log.Values[i] >= log.Values[i - 1];
  }
  ck.Check(monotone && log.Values.back() == 1.0 && log.Values.size() >= 10,
    name + ": " + std::to_string(log.Values.size()) + " progress events from 0, non-decreasing, last " +
      Fmt(log.Values.empty() ? -1.0 : log.Values.back()));
  const vtkIdType fullWork = mapper->GetNumberOfSegments();
  ck.Check(observed.V == plain.V && NonZero(plain) > 1000 && !mapper->GetLastRenderAborted(),
    name + ": image with progress bit-identical to the plain one (" + std::to_string(NonZero(plain)) +
      " covered pixels)");

  log.Values.clear();
  log.AbortAt = 0.25;
  const Image aborted = Render(mapper, cam, scene.Volume, w, h);
  size_t nan = 0, mismatch = 0;
  for (size_t k = 0; k < aborted.V.size(); ++k)
  {
    nan += std::isnan(aborted.V[k]);
    const size_t p = k / 4;
    const bool zero = aborted.V[4 * p] == 0 && aborted.V[4 * p + 1] == 0 &&
      aborted.V[4 * p + 2] == 0 && aborted.V[4 * p + 3] == 0;
    mismatch += !zero && aborted.V[k] != plain.V[k];
  }
  ck.Check(mapper->GetLastRenderAborted() && log.Values.back() < 0.5,
    name + ": aborted at progress " + Fmt(log.Values.back()));
  ck.Check(mapper->GetNumberOfSegments() < fullWork,
    name + ": the aborted render integrated fewer segments (" +
      std::to_string(mapper->GetNumberOfSegments()) + " of " + std::to_string(fullWork) + ")");
  ck.Check(nan == 0 && mismatch == 0 && NonZero(aborted) < NonZero(plain),
    name + ": aborted image: " + std::to_string(nan) + " NaN, " + std::to_string(mismatch) +
      " values differing from the full image outside zero tiles, " +
      std::to_string(NonZero(aborted)) + " covered pixels");

  log.AbortAt = 2.0;
  const Image again = Render(mapper, cam, scene.Volume, w, h);
  ck.Check(again.V == plain.V && !mapper->GetLastRenderAborted(),
    name + ": the render after an abort is complete and bit-identical");
  mapper->RemoveObserver(tag);
}

/// In a render window, an AbortCheckEvent observer that sets AbortRender stops the CPU path.
void CheckWindowAbort(Checker& ck, VolumeScene& scene, vtkCamera* cam)
{
  auto renderer = BlackRenderer(cam);
  renderer->AddVolume(scene.Volume);
  auto window = OffscreenWindow(renderer, 160, 120);
  window->Render();
  const Image full = FloatImage(scene.Mapper);
  int checks = 0;
  vtkNew<vtkCallbackCommand> abortCheck;
  abortCheck->SetClientData(&checks);
  abortCheck->SetCallback([](vtkObject* caller, unsigned long, void* clientData, void*) {
    if (++*static_cast<int*>(clientData) >= 1) // VTK polls at most 5 times a second
    {
      static_cast<vtkRenderWindow*>(caller)->SetAbortRender(1);
    }
  });
  window->AddObserver(vtkCommand::AbortCheckEvent, abortCheck);
  window->Render();
  const Image aborted = FloatImage(scene.Mapper);
  ck.Check(scene.Mapper->GetLastRenderAborted() && NonZero(aborted) < NonZero(full) &&
      NonZero(full) > 1000,
    "window: AbortRender set by an AbortCheckEvent observer stops the render (" +
      std::to_string(NonZero(aborted)) + " of " + std::to_string(NonZero(full)) +
      " covered pixels, " + std::to_string(checks) + " abort checks)");
  renderer->RemoveVolume(scene.Volume);
}
}

int TestProgressAbort(int argc, char* argv[])
{
  Checker ck;
  std::unique_ptr<VolumeScene> bracket = BracketScene(ck, argc, argv);
  if (!bracket)
  {
    return ck.Result();
  }
  VolumeScene& scene = *bracket;
  vtkNew<vtkCamera> cam;
  BracketCamera(cam);

  CheckCase(ck, scene, cam, "plain path");
  CheckWindowAbort(ck, scene, cam);
  scene.Mapper->AddIsosurface(80.0, 1.0, 1.0, 0.2, 0.5);
  CheckCase(ck, scene, cam, "feature path (isosurface)");
  scene.Mapper->RemoveAllIsosurfaces();
  scene.Mapper->SetRenderModeToRayCast(); // rows of rays are its tiles
  CheckCase(ck, scene, cam, "RAY_CAST");
  CheckWindowAbort(ck, scene, cam);
  ck.Check(scene.NoMessages(), "no error or warning");
  return ck.Result();
}
