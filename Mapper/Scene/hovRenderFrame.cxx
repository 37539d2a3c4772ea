#include "hovRenderFrame.h"

#include "hovViewCheck.h"                 // CheckView
#include "hovViewRays.h"                  // the pixel rays
#include "vtkHighOrderTransferFunction.h" // the table of the volume property

#include "hovTransferFunction.h" // HasExtinction

#include "vtkAlgorithm.h"                    // input update
#include "vtkCamera.h"                       // (complete type for the view check)
#include "vtkDataArray.h"                    // the scalars
#include "vtkUnstructuredGridBase.h"         // the input
#include "vtkUnstructuredGridVolumeMapper.h" // input, scalar selection, clipping planes
#include "vtkVolume.h"                       // matrix, property
#include "vtkVolumeProperty.h"               // independent components

#include <cmath>   // std::isfinite
#include <sstream> // messages

bool hov::RenderFrame::ValidateView()
{
  if (!this->Camera || !this->Volume || this->Width <= 0 || this->Height <= 0)
  {
    this->Error("RenderImage needs a camera, a volume and a positive size.");
    return false;
  }
  if (this->ImagePixels() == 0)
  {
    std::ostringstream text;
    text << "Cannot render: an image of " << this->Width << " x " << this->Height
         << " pixels exceeds the limit of " << MaxImagePixels << " pixels (16384 x 16384).";
    this->Error(text.str());
    return false;
  }
  const std::string why = hov::CheckView(this->Camera, this->Volume->GetMatrix(), this->Aspect);
  if (!why.empty())
  {
    this->Error("Cannot render: " + why + ".");
    return false;
  }
  const double* range = this->Settings.ViewDepthRange;
  if (this->Settings.ViewDepthClipping && !(std::isfinite(range[0]) && std::isfinite(range[1])))
  {
    std::ostringstream text;
    text << "Cannot render: the view-depth range [" << range[0] << ", " << range[1]
         << "] is not finite.";
    this->Error(text.str());
    return false;
  }
  this->SelectInput();
  return true;
}

void hov::RenderFrame::SelectInput()
{
  vtkUnstructuredGridVolumeMapper* mapper = this->Mapper;
  if (mapper->GetNumberOfInputConnections(0) > 0)
  {
    mapper->GetInputAlgorithm()->Update(); // RenderImage may run before any render
  }
  this->Input = mapper->GetInput();
  this->Scalars = ScalarSelection();
  int cellFlag = 0;
  vtkDataArray* scalars = this->Input
    ? vtkAbstractMapper::GetScalars(this->Input, mapper->GetScalarMode(),
        mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag)
    : nullptr;
  if (scalars)
  {
    ScalarSelection& s = this->Scalars;
    s.Array = scalars;
    s.Association = cellFlag;
    s.CellScalars = cellFlag == 1;
    const int nc = scalars->GetNumberOfComponents();
    if (nc > 1 && this->Settings.Vectors == VectorMode::Component)
    {
      s.Component = std::min(std::max(this->Settings.VectorComponent, 0), nc - 1);
      s.ComponentClamped = s.Component != this->Settings.VectorComponent;
    }
    if (nc == 1)
    {
      s.Component = 0;
    }
  }
}

hov::InputKey hov::RenderFrame::Key() const
{
  InputKey key;
  key.Input = this->Input;
  key.InputTime = this->Input ? this->Input->GetMTime() : 0;
  key.Array = this->Scalars.Array;
  key.ArrayTime = this->Scalars.Array ? this->Scalars.Array->GetMTime() : 0;
  key.Component = this->Scalars.Component;
  key.CellScalars = this->Scalars.CellScalars;
  return key;
}

bool hov::RenderFrame::SetupRays(ViewRays& rays, int width, int height) const
{
  if (!rays.Setup(this->Camera, this->Volume->GetMatrix(), width, height, this->Aspect))
  {
    this->Error("Singular camera or volume matrix: nothing rendered.");
    return false;
  }
  const int ignored = rays.SetupClipping(this->Mapper, this->Camera, this->Volume->GetMatrix(),
    this->Settings.ViewDepthClipping ? this->Settings.ViewDepthRange : nullptr);
  if (ignored > 0)
  {
    this->Warning(std::to_string(ignored) +
      " clipping plane(s) with a zero normal or a NaN/Inf normal or origin define no "
      "half-space: ignored.");
  }
  return true;
}

bool hov::RenderFrame::UpdateTransferFunction(
  vtkHighOrderTransferFunction* tf, double gpuTolerance, bool& rebuilt) const
{
  vtkVolumeProperty* property = this->Volume->GetProperty();
  tf->SetOpacitySemantics(static_cast<int>(this->Settings.Semantics));
  tf->SetGPUTolerance(gpuTolerance);
  tf->SetEmissionScale(this->Settings.EmissionScale);
  // One component of a multi-component array with independent components
  // uses that component's functions; everything else uses component 0's.
  const int component = this->Scalars.Component;
  const bool independent = component > 0 && property->GetIndependentComponents();
  tf->SetComponent(independent ? std::min(component, 3) : 0);
  const int buildsBefore = tf->GetBuildCount();
  tf->Update(property);
  rebuilt = tf->GetBuildCount() != buildsBefore;
  for (int i = 0; rebuilt && i < tf->GetNumberOfMessages(); ++i)
  {
    this->Warning(std::string("Transfer function: ") + tf->GetMessage(i));
  }
  // Nothing absorbs: nothing to see, unless the glow does not need extinction.
  return tf->GetTable().HasExtinction() ||
    this->Settings.Emission == EmissionModel::WilhelmsVanGelder;
}

void hov::RenderFrame::NoVisibleVolume(bool warn) const
{
  this->NotDrawnReason = "The transfer function has no opacity anywhere (and the emission model "
                         "needs extinction to glow): the volume is invisible; nothing rendered.";
  this->NotDrawnWarned = warn;
  if (warn)
  {
    this->Warning(this->NotDrawnReason);
  }
}

void hov::RenderFrame::NoRenderedCell(vtkIdType cells) const
{
  std::ostringstream text;
  text << "The image is empty: none of the input's " << cells
       << " cells is rendered in this mode (see the warnings given when the input was read).";
  this->NotDrawnReason = text.str();
  this->NotDrawnWarned = this->InputReported;
}
