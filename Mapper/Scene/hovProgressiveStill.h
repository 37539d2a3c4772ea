/**
 * @class   hov::ProgressiveStill
 * @brief   Progressive still frames of vtkHighOrderVolumeMapper in a window
 *          driven by a vtkRenderWindowInteractor (README, "Interaction").
 *
 * VTK draws a frame in one Render() call, and a still frame that takes
 * seconds would freeze the UI. As ParaView's progressive passes do, a still
 * frame whose estimated exact cost is above the mapper's ProgressiveTime is
 * drawn in levels, one per Render(): first one ray per f x f block (f fitting
 * the interactor's DesiredUpdateRate), then f / 4, ..., then the exact frame.
 * After each level a repeating timer of the interactor (10 ms, created for
 * the refinement and destroyed after it, never inside a TimerEvent: VTK 9.1's
 * X interactor iterates over its timers while invoking it) asks for the next
 * Render(); the application's event loop runs in between, so the UI stays live. The exact level is abortable (the window's
 * AbortCheckEvent, SetAbortExecute, and X events pending on the window);
 * an aborted level shows the last completed one and is retried by the timer.
 * Only a still frame that follows an interactive frame (the mouse release)
 * starts a refinement: a still frame of a new view drawn without interaction
 * (a script rendering one view after another, a screenshot) is exact at once,
 * so no caller ever reads a coarse level it did not ask for. A change of the
 * view during a refinement starts it again at the coarse level; an
 * interactive frame cancels it.
 *
 * Without an initialized interactor (offscreen, RenderImage) every still frame
 * is exact at once.
 *
 * Thread safety: rendering thread only.
 * @sa hov::InteractionBudget, vtkHighOrderVolumeMapper
 */
#ifndef hovProgressiveStill_h
#define hovProgressiveStill_h

#include "vtkNew.h"         // the timer observer
#include "vtkWeakPointer.h" // the interactor
#include "vtkType.h" // vtkMTimeType

#include <vector> // the last completed level

class vtkCallbackCommand;
class vtkObject;
class vtkRenderWindowInteractor;
class vtkRenderer;
class vtkVolume;
class vtkAbstractMapper;

namespace hov
{
class ProgressiveStill
{
public:
  ProgressiveStill();
  ~ProgressiveStill();

  /**
   * The pixels per ray of a still frame of @p volume in @p renderer (1: exact)
   * and whether it is a progressive level. @p estimate: the exact frame's
   * estimated seconds (-1 unknown); @p threshold: ProgressiveTime (<= 0: off);
   * @p coarse: the factor that fits the interactive budget; @p mayStart:
   * whether a new refinement may start (the previous frame was interactive
   * or a refinement is under way; see the class doc).
   */
  int Level(vtkRenderer* renderer, vtkVolume* volume, vtkAbstractMapper* mapper, double estimate,
    double threshold, int coarse, bool mayStart);

  /// The level of the last Level() call is drawn at @p factor pixels per ray
  /// (another path's budget may change it): the next level is finer than that.
  void Drawn(int factor)
  {
    if (this->Running && factor > 1)
    {
      this->Current = factor;
    }
  }

  /// Whether the frame of the last Level() call is a progressive one.
  bool Active() const { return this->Running; }

  /// The frame of the last Level() finished (@p aborted or complete) with
  /// @p rgba (@p pixels x 4 floats, the published image): the next level or
  /// a retry is scheduled. Returns the image to show instead of an aborted
  /// level (null if none).
  const float* Finished(bool aborted, const float* rgba, size_t pixels);

  /// An interactive frame or a change of mode: no refinement pending.
  void Cancel();

private:
  static void OnTimer(vtkObject* caller, unsigned long, void* clientData, void* callData);
  void Schedule();
  void StopTimer();

  std::vector<vtkMTimeType> Key;
  int Current = 1;
  bool Running = false;
  bool Pending = false; ///< a level waits for the timer
  bool InTimer = false; ///< inside our TimerEvent (no timer may be created or destroyed)
  std::vector<float> Completed; ///< the last completed level's image
  vtkWeakPointer<vtkRenderWindowInteractor> Interactor;
  unsigned long Observer = 0;
  int TimerId = -1;
  vtkNew<vtkCallbackCommand> Callback;
};
}

#endif
