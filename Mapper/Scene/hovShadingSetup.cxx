#include "hovShadingSetup.h"

#include "vtkHighOrderTransferFunction.h" // PrintFrameState

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm> // std::copy

void hov::ReadLights(vtkRenderer* renderer, vtkCamera* camera, std::vector<ShadingLight>& lights,
  bool& twoSided, bool& singleHeadlight, double ambientLight[3])
{
  lights.clear();
  ambientLight[0] = ambientLight[1] = ambientLight[2] = 0.0;
  if (!renderer)
  {
    // A white headlight along the direction of projection.
    hov::ShadingLight light;
    double dop[3];
    camera->GetDirectionOfProjection(dop);
    std::copy(dop, dop + 3, light.Direction);
    camera->GetPosition(light.Position);
    lights.push_back(light);
    twoSided = true;
    singleHeadlight = true;
    return;
  }
  int headlights = 0;
  bool unitIntensity = true;
  vtkLightCollection* collection = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  while (vtkLight* l = collection->GetNextLight(it))
  {
    if (!l->GetSwitch())
    {
      continue;
    }
    hov::ShadingLight light;
    double position[3], focal[3], ambient[3];
    l->GetTransformedPosition(position);
    l->GetTransformedFocalPoint(focal);
    for (int k = 0; k < 3; ++k)
    {
      light.Direction[k] = focal[k] - position[k];
      light.Position[k] = position[k];
    }
    if (light.Direction[0] == 0.0 && light.Direction[1] == 0.0 && light.Direction[2] == 0.0)
    {
      light.Direction[2] = -1.0; // as vtkLight's default
    }
    l->GetDiffuseColor(light.Color);
    light.Intensity = l->GetIntensity();
    light.Positional = l->GetPositional() != 0;
    l->GetAttenuationValues(light.Attenuation);
    light.ConeAngle = l->GetConeAngle();
    light.Exponent = l->GetExponent();
    l->GetAmbientColor(ambient);
    for (int k = 0; k < 3; ++k)
    {
      ambientLight[k] += light.Intensity * ambient[k];
    }
    headlights += l->LightTypeIsHeadlight() ? 1 : 0;
    unitIntensity = unitIntensity && light.Intensity == 1.0;
    lights.push_back(light);
  }
  twoSided = renderer->GetTwoSidedLighting() != 0;
  singleHeadlight = lights.size() == 1 && headlights == 1 && unitIntensity;
}

void hov::ReadVolumeShading(
  vtkVolume* volume, vtkRenderer* renderer, vtkCamera* camera, bool composite, ShadingFrameSettings& out)
{
  out = ShadingFrameSettings();
  vtkVolumeProperty* property = volume ? volume->GetProperty() : nullptr;
  if (!property || !camera || !composite)
  {
    return;
  }
  out.Shade = property->GetShade(0) != 0;
  if (property->HasGradientOpacity(0) && !property->GetDisableGradientOpacity(0) &&
    property->GetTransferFunctionMode() == vtkVolumeProperty::TF_1D)
  {
    vtkPiecewiseFunction* go = property->GetGradientOpacity(0);
    const int n = go ? go->GetSize() : 0;
    bool constantOne = true;
    for (int i = 0; i < n; ++i)
    {
      double node[4];
      go->GetNodeValue(i, node);
      out.GradientOpacityNodes.push_back(hov::OpacityNode{ node[0], node[1] });
      constantOne = constantOne && node[1] == 1.0;
    }
    // vtkVolumeProperty::GetGradientOpacity() creates a constant 1 when none
    // was set (HasGradientOpacity() is then true): no gradient opacity.
    out.GradientOpacity = !out.GradientOpacityNodes.empty() && !constantOne;
    if (!out.GradientOpacity)
    {
      out.GradientOpacityNodes.clear();
    }
  }
  if (!out.Shade)
  {
    return;
  }
  out.Material.Ambient = property->GetAmbient(0);
  out.Material.Diffuse = property->GetDiffuse(0);
  out.Material.Specular = property->GetSpecular(0);
  out.Material.SpecularPower = property->GetSpecularPower(0);
  bool singleHeadlight = false;
  ReadLights(renderer, camera, out.Lights, out.Material.TwoSidedLighting, singleHeadlight,
    out.AmbientLight);
  out.Ambient = singleHeadlight ? AmbientTerm::MaterialColor : AmbientTerm::LightAmbient;
}

void hov::PrintFrameState(std::ostream& os, vtkIndent indent, const ShadingFrameSettings& shading,
  const std::vector<std::string>& unhonoured, vtkHighOrderTransferFunction* tf)
{
  const ShadingMaterial& m = shading.Material;
  os << indent << "Shading (last frame): Shade " << shading.Shade << ", ambient " << m.Ambient
     << ", diffuse " << m.Diffuse << ", specular " << m.Specular << ", specular power "
     << m.SpecularPower << ", two-sided " << m.TwoSidedLighting << ", "
     << (shading.Ambient == AmbientTerm::MaterialColor ? "ambient ka c" : "ambient ka sum I La")
     << ", lights " << shading.Lights.size() << "\n";
  os << indent << "GradientOpacity (last frame): " << shading.GradientOpacity << " ("
     << shading.GradientOpacityNodes.size() << " nodes)\n";
  os << indent << "UnhonouredFeatures: " << unhonoured.size() << "\n";
  for (const std::string& text : unhonoured)
  {
    os << indent.GetNextIndent() << text << "\n";
  }
  os << indent << "TransferFunction:\n";
  if (tf)
  {
    tf->PrintSelf(os, indent.GetNextIndent());
  }
}
