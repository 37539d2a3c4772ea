// Interaction the VTK way (issue 19; README, "Interaction") on the bundled
// bracket at 96 x 72 in every render mode, in a window with an interactor
// whose timers the test fires itself (no event loop; no timing assertions):
//  1. The non-interactive render (AutoAdjustImageSampleDistance off) is the
//     reference.
//  2. A budget of 1 us (DesiredUpdateRate 1e6: the volume's allocated render
//     time) gives an interactive frame: LastRenderWasInteractive, at least 2
//     pixels per ray, fewer rays than pixels, a finite image that differs.
//  3. The still frame after it (DesiredUpdateRate 0.0001) equals the
//     reference bit for bit (once its progressive levels, if any, are done).
//  4. Progressive still frames (ProgressiveTime 1e-9: every still frame is
//     "slow"): a new view without interaction is exact at once; after an
//     interactive frame the release first gives a coarse level with a one-shot timer
//     pending; firing the timers renders finer levels up to the exact one,
//     equal bit for bit to the non-interactive render of that view.
//  5. Every mode: an AbortCheckEvent observer that sets AbortRender stops a
//     still frame (LastRenderAborted); the next still frame is complete and
//     equals the non-interactive render. An abort of a progressive exact
//     level shows the last completed level instead of a partial image.
//  6. RAY_CAST on linear cells: its reduced frame (InteractiveSubsampling 4)
//     is drawn by the CPU path (GetLastDrawingMode) and equals CPU_ACCURATE's
//     bit for bit (so would the ray caster's: its linear cells use the same
//     closed forms); the still frame after it is the ray caster's.
#include "hovTestScenes.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

using namespace hovTest;

namespace
{
/// An interactor whose timers fire when the test says so (FireTimers()).
class TimerInteractor : public vtkRenderWindowInteractor
{
public:
  static TimerInteractor* New();
  vtkTypeMacro(TimerInteractor, vtkRenderWindowInteractor);
  std::vector<int> Pending; ///< the timers that exist
  /// Fires every timer once; returns how many fired.
  size_t FireTimers()
  {
    const std::vector<int> ids = this->Pending;
    for (int id : ids)
    {
      int timerId = id;
      this->InvokeEvent(vtkCommand::TimerEvent, &timerId);
      if (this->IsOneShotTimer(timerId))
      {
        this->DestroyTimer(timerId);
      }
    }
    return ids.size();
  }

protected:
  int InternalCreateTimer(int timerId, int, unsigned long) override
  {
    this->Pending.push_back(timerId);
    return timerId;
  }
  int InternalDestroyTimer(int platformId) override
  {
    this->Pending.erase(
      std::remove(this->Pending.begin(), this->Pending.end(), platformId), this->Pending.end());
    return 1;
  }
};
vtkStandardNewMacro(TimerInteractor);

const int W = 96, H = 72;

struct AbortRequest
{
  bool Armed = false;
};

/// The next abort check aborts (VTK polls the AbortCheckEvent at most 5 times
/// a second: wait that long first).
void Arm(AbortRequest& r)
{
  std::this_thread::sleep_for(std::chrono::milliseconds(250));
  r.Armed = true;
}

/// Renders still frames (firing the progressive timers) until an exact one.
int StillFrame(vtkRenderWindow* win, TimerInteractor* iren, vtkHighOrderVolumeMapper* mapper)
{
  win->SetDesiredUpdateRate(0.0001);
  win->Render();
  int levels = 1;
  while (mapper->GetLastSubsampling() > 1 && levels < 20 && iren->FireTimers() > 0)
  {
    ++levels;
  }
  return levels;
}

void CheckMode(Checker& ck, VolumeScene& scene, vtkCamera* cam, int mode, const std::string& name)
{
  vtkHighOrderVolumeMapper* mapper = scene.Mapper;
  mapper->SetRenderMode(mode);
  auto renderer = BlackRenderer(cam);
  renderer->AddVolume(scene.Volume);
  auto win = OffscreenWindow(renderer, W, H);
  vtkNew<TimerInteractor> iren;
  iren->SetRenderWindow(win);
  iren->Initialize();

  // 1-3: reference, interactive frame, still frame.
  const Image ref = NonInteractiveRender(win, mapper);
  win->SetDesiredUpdateRate(1e6);
  win->Render();
  const Image fast = FloatImage(mapper);
  const bool interactive = mapper->GetLastRenderWasInteractive();
  const int f = mapper->GetLastSubsampling();
  const vtkIdType rays = mapper->GetNumberOfRays();
  const DiffStats dFast = Diff(ref, fast);
  std::cout << "[measured] " << name << ": interactive frame f = " << f << ", " << rays
            << " rays for " << W * H << " pixels, vs reference " << dFast.Str() << std::endl;
  ck.Check(interactive && f >= 2 && rays > 0 && rays <= W * H / 4 && CheckImage(fast).Ok() &&
      CheckImage(fast).Covered > 100 && dFast.Max > 0.0,
    name + ": a 1 us budget gives a coarser, cheaper interactive frame");
  const int levels = StillFrame(win, iren, mapper);
  const Image still = FloatImage(mapper);
  ck.Check(!mapper->GetLastRenderWasInteractive() && mapper->GetLastSubsampling() == 1 &&
      still.V == ref.V && CheckImage(ref).Covered > 1000,
    name + ": the still frame after interaction equals the non-interactive render bit for bit (" +
      std::to_string(levels) + " level(s))");

  // 4: a new view drawn without interaction (a script's loop of screenshots)
  // is exact at once, however slow; after interaction it is progressive.
  mapper->SetProgressiveTime(1e-9);
  cam->Azimuth(10.0);
  win->SetDesiredUpdateRate(0.0001);
  win->Render();
  const int direct = mapper->GetLastSubsampling();
  const Image directImage = FloatImage(mapper);
  ck.Check(direct == 1 && directImage.V == NonInteractiveRender(win, mapper).V,
    name + ": a still frame of a new view without interaction is exact at once (f = " +
      std::to_string(direct) + ")");
  cam->Azimuth(10.0);
  win->SetDesiredUpdateRate(1e6);
  win->Render(); // interaction
  win->SetDesiredUpdateRate(0.0001);
  win->Render(); // the release
  const int coarse = mapper->GetLastSubsampling();
  const Image coarseImage = FloatImage(mapper);
  const bool pending = !iren->Pending.empty();
  const int progressiveLevels = StillFrame(win, iren, mapper);
  const Image refined = FloatImage(mapper);
  const Image ref2 = NonInteractiveRender(win, mapper);
  ck.Check(coarse > 1 && pending && CheckImage(coarseImage).Ok() &&
      mapper->GetLastSubsampling() == 1 && refined.V == ref2.V,
    name + ": progressive still frame: level f = " + std::to_string(coarse) + " at once, " +
      std::to_string(progressiveLevels) + " levels by timer, the last equal to the non-interactive render");

  // 6: RAY_CAST's reduced frames of linear cells come from the CPU path.
  if (mode == vtkHighOrderVolumeMapper::RAY_CAST)
  {
    mapper->SetInteractiveSubsampling(4);
    win->SetDesiredUpdateRate(1e6);
    win->Render();
    const Image rayReduced = FloatImage(mapper);
    const int fRay = mapper->GetLastSubsampling();
    const int drawnBy = mapper->GetLastDrawingMode();
    mapper->SetRenderMode(vtkHighOrderVolumeMapper::CPU_ACCURATE);
    win->Render();
    const Image cpuReduced = FloatImage(mapper);
    mapper->SetRenderMode(mode);
    mapper->SetInteractiveSubsampling(0);
    StillFrame(win, iren, mapper);
    const int stillDrawnBy = mapper->GetLastDrawingMode();
    ck.Check(fRay == 4 && drawnBy == vtkHighOrderVolumeMapper::CPU_ACCURATE &&
        stillDrawnBy == vtkHighOrderVolumeMapper::RAY_CAST && mapper->GetLastSubsampling() == 1 &&
        rayReduced.V == cpuReduced.V && CheckImage(rayReduced).Covered > 100,
      name + ": the reduced frame of linear cells is the CPU path's, bit for bit (f = " +
        std::to_string(fRay) + ")");
  }

  // 5: abort (CPU modes: between tile batches; OPENGL_PROJECTION: between
  // groups of cells).
  {
    AbortRequest request;
    vtkNew<vtkCallbackCommand> abortCheck;
    abortCheck->SetClientData(&request);
    abortCheck->SetCallback([](vtkObject* caller, unsigned long, void* clientData, void*) {
      auto* r = static_cast<AbortRequest*>(clientData);
      if (r->Armed)
      {
        r->Armed = false;
        static_cast<vtkRenderWindow*>(caller)->SetAbortRender(1);
      }
    });
    const unsigned long tag = win->AddObserver(vtkCommand::AbortCheckEvent, abortCheck);
    // A progressive exact level aborted: the last completed level is shown.
    cam->Azimuth(10.0);
    win->SetDesiredUpdateRate(1e6);
    win->Render(); // interaction, then the release
    win->SetDesiredUpdateRate(0.0001);
    win->Render();
    while (mapper->GetLastSubsampling() >= 8 && iren->FireTimers() > 0)
    {
      // levels f0, f0 / 4, ...: the one before the exact level has f < 8
    }
    const Image level = FloatImage(mapper);
    Arm(request);
    iren->FireTimers(); // the exact level, aborted at its first check
    const Image shown = FloatImage(mapper);
    std::cout << "[measured] " << name << ": exact level aborted " << mapper->GetLastRenderAborted()
              << ", f " << mapper->GetLastSubsampling() << ", shown vs last level "
              << Diff(level, shown).Str() << std::endl;
    ck.Check(mapper->GetLastRenderAborted() && shown.V == level.V && shown.V != ref2.V &&
        CheckImage(shown).Covered > 100,
      name + ": an aborted exact level shows the last completed level");
    // A plain still frame aborted, then the next one complete.
    mapper->SetProgressiveTime(0.0);
    cam->Azimuth(10.0);
    win->SetDesiredUpdateRate(0.0001);
    Arm(request);
    win->Render();
    const bool aborted = mapper->GetLastRenderAborted();
    win->RemoveObserver(tag);
    win->Render();
    const Image complete = FloatImage(mapper);
    const Image ref3 = NonInteractiveRender(win, mapper);
    ck.Check(aborted && !mapper->GetLastRenderAborted() && complete.V == ref3.V,
      name + ": AbortCheckEvent stops a still frame; the next still frame is complete");
  }
  mapper->SetProgressiveTime(0.5);
  renderer->RemoveVolume(scene.Volume);
  iren->SetRenderWindow(nullptr);
}
}

int TestInteraction(int argc, char* argv[])
{
  Checker ck;
  std::unique_ptr<VolumeScene> bracket = BracketScene(ck, argc, argv);
  if (!bracket)
  {
    return ck.Result();
  }
  VolumeScene& scene = *bracket;
  const struct
  {
    int Mode;
    const char* Name;
  } modes[] = { { vtkHighOrderVolumeMapper::CPU_ACCURATE, "CPU_ACCURATE" },
    { vtkHighOrderVolumeMapper::OPENGL_PROJECTION, "OPENGL_PROJECTION" },
    { vtkHighOrderVolumeMapper::RAY_CAST, "RAY_CAST" } };
  for (const auto& m : modes)
  {
    vtkNew<vtkCamera> cam;
    BracketCamera(cam);
    CheckMode(ck, scene, cam, m.Mode, m.Name);
  }
  ck.Check(scene.NoMessages(), "no error or warning");
  return ck.Result();
}
