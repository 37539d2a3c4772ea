#include "hovPropertyAudit.h"

#include "hovRenderFrame.h" // the frame

#include "vtkDataArray.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm> // std::find

namespace
{
const char* ModeName(hov::RenderMode mode)
{
  switch (mode)
  {
    case hov::RenderMode::OpenGLProjection:
      return "OPENGL_PROJECTION";
    case hov::RenderMode::RayCast:
      return "RAY_CAST";
    default:
      return "CPU_ACCURATE";
  }
}

/// True if every node of @p f has the value 1 (what GetGradientOpacity() creates).
bool ConstantOne(vtkPiecewiseFunction* f)
{
  for (int i = 0; f && i < f->GetSize(); ++i)
  {
    double node[4];
    f->GetNodeValue(i, node);
    if (node[1] != 1.0)
    {
      return false;
    }
  }
  return true;
}

/// True if a node of @p f has a midpoint other than 0.5 or a sharpness other than 0.
bool HasShapedNodes(vtkPiecewiseFunction* f)
{
  for (int i = 0; f && i < f->GetSize(); ++i)
  {
    double node[4];
    f->GetNodeValue(i, node);
    if (node[2] != 0.5 || node[3] != 0.0)
    {
      return true;
    }
  }
  return false;
}
}

std::vector<std::string> hov::PropertyAudit::List(const RenderFrame& frame, vtkVolumeProperty* p)
{
  std::vector<std::string> out;
  if (!p)
  {
    return out;
  }
  const FrameSettings& s = frame.Settings;
  // RenderImage in OPENGL_PROJECTION renders the CPU_ACCURATE image.
  const RenderMode effective =
    s.Mode == RenderMode::OpenGLProjection && !frame.Renderer ? RenderMode::CPUAccurate : s.Mode;
  const std::string mode = ModeName(effective);
  const std::string in = " (" + mode + " mode)";
  // InterpolationType (NEAREST is vtkVolumeProperty's default) is honoured as
  // VTK's unstructured mappers define it: they ignore it and interpolate
  // within every cell, as this mapper does.
  const int components =
    frame.Scalars.Array ? frame.Scalars.Array->GetNumberOfComponents() : 1;
  const int rendered = std::max(frame.Scalars.Component, 0);
  if (components > 1 && !p->GetIndependentComponents())
  {
    out.push_back("vtkVolumeProperty IndependentComponents off (dependent components: colour "
                  "from the components, opacity from the last) is not honoured" +
      in + ": the " +
      (frame.Scalars.Component < 0 ? std::string("magnitude")
                                   : "component " + std::to_string(rendered)) +
      " is rendered with component 0's functions");
  }
  for (int c = 0; c < VTK_MAX_VRCOMP; ++c)
  {
    if (p->GetComponentWeight(c) != 1.0)
    {
      out.push_back("vtkVolumeProperty ComponentWeight of component " + std::to_string(c) + " (" +
        std::to_string(p->GetComponentWeight(c)) + ") is not honoured" + in);
    }
  }
  for (int c = 1; c < VTK_MAX_VRCOMP; ++c)
  {
    if (p->GetShade(c) && p->GetShade(c) != p->GetShade(0))
    {
      out.push_back("vtkVolumeProperty Shade of component " + std::to_string(c) +
        " is not honoured" + in + ": the volume is shaded as component 0 says");
    }
    if (p->HasGradientOpacity(c) && p->GetTransferFunctionMode() == vtkVolumeProperty::TF_1D &&
      !p->GetDisableGradientOpacity(c) && !ConstantOne(p->GetGradientOpacity(c)))
    {
      out.push_back("vtkVolumeProperty gradient opacity of component " + std::to_string(c) +
        " is not honoured" + in + ": component 0's is used");
    }
  }
  if (s.Shading.GradientOpacity && HasShapedNodes(p->GetGradientOpacity(0)))
  {
    out.push_back("vtkVolumeProperty gradient-opacity midpoints and sharpness are not honoured" +
      in + ": the function is linear between its nodes");
  }
  // RAY_CAST shades and applies gradient opacity; OPENGL_PROJECTION does not.
  const bool otherMode = effective == RenderMode::OpenGLProjection;
  const bool features = s.NumberOfIsosurfaces() > 0 || !s.ColorArray.empty() ||
    !s.IsosurfaceArray.empty();
  const char* why = otherMode ? "" : " with isosurfaces or a separate colour or isosurface array";
  const bool ignored = otherMode || (features && effective == RenderMode::CPUAccurate);
  if (s.Shading.Shade && ignored)
  {
    out.push_back("vtkVolumeProperty Shade (volume shading) is not applied in " + mode + " mode" +
      why + ": the volume is unshaded");
  }
  if (s.Shading.GradientOpacity && ignored)
  {
    out.push_back("vtkVolumeProperty gradient opacity is not applied in " + mode + " mode" + why);
  }
  if (p->GetTransferFunctionMode() == vtkVolumeProperty::TF_2D)
  {
    out.push_back("vtkVolumeProperty TransferFunctionMode TF_2D (2D transfer functions) is not "
                  "honoured" + in + ": the 1D functions are used");
  }
  if (p->GetNumberOfLabels() > 0 || p->HasLabelGradientOpacity())
  {
    out.push_back("vtkVolumeProperty label-map functions (SetLabelColor, SetLabelScalarOpacity, "
                  "SetLabelGradientOpacity) are not honoured" + in);
  }
  if (p->GetSliceFunction())
  {
    out.push_back("vtkVolumeProperty SliceFunction (SLICE blending) is not honoured" + in);
  }
  if (p->GetUseClippedVoxelIntensity())
  {
    out.push_back("vtkVolumeProperty UseClippedVoxelIntensity is not honoured" + in +
      ": gradients are those of the field");
  }
  return out;
}

int hov::PropertyAudit::Check(const RenderFrame& frame, vtkVolumeProperty* property)
{
  std::vector<std::string> now = List(frame, property);
  int warned = 0;
  for (const std::string& text : now)
  {
    if (std::find(this->Last.begin(), this->Last.end(), text) == this->Last.end())
    {
      frame.Warning(text + ".");
      ++warned;
    }
  }
  this->Last.swap(now);
  return warned;
}
