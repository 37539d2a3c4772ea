#include "hovRayCastShading.h"

#include "hovRenderFrame.h" // the frame

#include "hovCurvedSegment.h" // CurvedSegmentSettings

#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkVolume.h"

#include <algorithm> // std::equal

void hov::RayCastShading::Prepare(const RenderFrame& frame, CurvedSegmentSettings& settings)
{
  settings.Shading = nullptr;
  settings.GradientOpacity = nullptr;
  const ShadingFrameSettings& s = frame.Settings.Shading;
  if (!s.Active() || !frame.Volume)
  {
    return;
  }
  if (s.Shade)
  {
    vtkNew<vtkMatrix4x4> inverse;
    vtkMatrix4x4::Invert(frame.Volume->GetMatrix(), inverse);
    this->Lights = s.Lights;
    for (ShadingLight& light : this->Lights)
    {
      double p[4] = { light.Position[0], light.Position[1], light.Position[2], 1.0 };
      double d[4] = { light.Direction[0], light.Direction[1], light.Direction[2], 0.0 };
      inverse->MultiplyPoint(p, p);
      inverse->MultiplyPoint(d, d);
      for (int k = 0; k < 3; ++k)
      {
        light.Position[k] = p[k] / (p[3] != 0.0 ? p[3] : 1.0);
        light.Direction[k] = d[k];
      }
    }
    this->Shading = VolumeShadingSettings();
    this->Shading.Shade = true;
    this->Shading.Material = s.Material;
    this->Shading.Ambient = s.Ambient;
    std::copy(s.AmbientLight, s.AmbientLight + 3, this->Shading.AmbientLight);
    this->Shading.Lights = this->Lights.data();
    this->Shading.LightCount = static_cast<int>(this->Lights.size());
    settings.Shading = &this->Shading;
  }
  if (s.GradientOpacity)
  {
    const auto same = [](const OpacityNode& a, const OpacityNode& b) {
      return a.X == b.X && a.Opacity == b.Opacity;
    };
    if (!this->Built || this->Nodes.size() != s.GradientOpacityNodes.size() ||
      !std::equal(this->Nodes.begin(), this->Nodes.end(), s.GradientOpacityNodes.begin(), same))
    {
      this->Nodes = s.GradientOpacityNodes;
      this->Built = true;
      GradientOpacitySpec spec;
      spec.Nodes = this->Nodes;
      std::vector<std::string> messages;
      this->GradientOpacity.Build(spec, &messages);
      for (const std::string& m : messages)
      {
        frame.Warning("Gradient opacity: " + m + ".");
      }
    }
    if (!this->GradientOpacity.IsIdentity())
    {
      settings.GradientOpacity = &this->GradientOpacity;
    }
  }
}
