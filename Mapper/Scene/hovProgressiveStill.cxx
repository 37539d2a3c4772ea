#include "hovProgressiveStill.h"

#include "vtkAbstractMapper.h"         // MTime
#include "vtkCallbackCommand.h"        // the timer observer
#include "vtkCamera.h"                 // MTime
#include "vtkCommand.h"                // TimerEvent
#include "vtkDataSet.h"                // the input's MTime
#include "vtkRenderWindow.h"           // size, interactor
#include "vtkRenderWindowInteractor.h" // timers
#include "vtkRenderer.h"               // camera, size
#include "vtkVolume.h"                 // MTime

#include <algorithm> // std::max

hov::ProgressiveStill::ProgressiveStill()
{
  this->Callback->SetCallback(&ProgressiveStill::OnTimer);
  this->Callback->SetClientData(this);
}

hov::ProgressiveStill::~ProgressiveStill()
{
  if (this->Interactor && this->Observer)
  {
    this->StopTimer();
    this->Interactor->RemoveObserver(this->Observer);
  }
}

void hov::ProgressiveStill::StopTimer()
{
  // Never from inside a TimerEvent: VTK 9.1's X interactor iterates over its
  // timers while it invokes the event.
  if (this->Interactor && this->TimerId >= 0 && !this->InTimer)
  {
    this->Interactor->DestroyTimer(this->TimerId);
    this->TimerId = -1;
  }
}

int hov::ProgressiveStill::Level(vtkRenderer* renderer, vtkVolume* volume,
  vtkAbstractMapper* mapper, double estimate, double threshold, int coarse, bool mayStart)
{
  vtkRenderWindow* window = renderer->GetRenderWindow();
  vtkRenderWindowInteractor* iren = window ? window->GetInteractor() : nullptr;
  if (!(threshold > 0.0) || !iren || !iren->GetInitialized() || !iren->GetEnabled())
  {
    this->Cancel();
    return 1;
  }
  if (!this->Running)
  {
    this->StopTimer(); // the last refinement's timer, once outside its event
  }
  vtkDataSet* input = vtkDataSet::SafeDownCast(mapper->GetInputDataObject(0, 0));
  const int* size = renderer->GetSize();
  const std::vector<vtkMTimeType> key = { renderer->GetActiveCamera()->GetMTime(),
    volume->GetMTime(), mapper->GetMTime(), input ? input->GetMTime() : 0,
    static_cast<vtkMTimeType>(size[0]), static_cast<vtkMTimeType>(size[1]) };
  if (key != this->Key)
  {
    // A new view: coarse first if the exact frame is slow.
    this->Key = key;
    this->Completed.clear();
    const bool refining = this->Running;
    this->Current = (mayStart || refining) && estimate > threshold && coarse > 1 ? coarse : 1;
    this->Running = this->Current > 1;
  }
  if (this->Running && this->Interactor != iren)
  {
    if (this->Interactor && this->Observer)
    {
      this->StopTimer();
      this->Interactor->RemoveObserver(this->Observer);
    }
    this->Interactor = iren;
    this->Observer = iren->AddObserver(vtkCommand::TimerEvent, this->Callback);
    this->TimerId = -1;
  }
  return this->Running ? this->Current : 1;
}

const float* hov::ProgressiveStill::Finished(bool aborted, const float* rgba, size_t pixels)
{
  if (!this->Running)
  {
    return nullptr;
  }
  if (aborted)
  {
    this->Schedule(); // retried once the pending events are handled
    return this->Completed.size() == 4 * pixels ? this->Completed.data() : nullptr;
  }
  if (this->Current == 1)
  {
    this->Running = false; // the exact frame: done
    this->Completed.clear();
    this->StopTimer();
    return nullptr;
  }
  this->Completed.assign(rgba, rgba + 4 * pixels);
  this->Current = this->Current >= 4 ? this->Current / 4 : 1;
  this->Schedule();
  return nullptr;
}

void hov::ProgressiveStill::Cancel()
{
  this->Running = false;
  this->Pending = false;
  this->Key.clear();
  this->Completed.clear();
  this->StopTimer();
}

void hov::ProgressiveStill::Schedule()
{
  // One repeating timer while refining (creating or destroying timers inside
  // VTK 9.1's TimerEvent is not safe): each tick renders a pending level.
  this->Pending = true;
  if (this->Interactor && this->TimerId < 0 && !this->InTimer)
  {
    this->TimerId = this->Interactor->CreateRepeatingTimer(10);
  }
}

void hov::ProgressiveStill::OnTimer(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* self = static_cast<ProgressiveStill*>(clientData);
  const int id = callData ? *static_cast<int*>(callData) : -1;
  if (id != self->TimerId || self->TimerId < 0 || self->InTimer)
  {
    return;
  }
  if (self->Running && self->Pending && self->Interactor)
  {
    self->Pending = false;
    self->InTimer = true;
    self->Interactor->Render(); // the next level
    self->InTimer = false;
  }
}
