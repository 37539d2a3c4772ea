#include "hovFeatureSetup.h"

#include "hovShadingSetup.h" // ReadLights

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkMatrix4x4.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGridBase.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm> // std::copy, std::equal
#include <cmath>     // std::isfinite, std::sqrt

bool hov::FeatureSetup::PrepareField(const std::string& name, int component,
  const char* what, vtkUnstructuredGridBase* input, FieldCache& cache, std::string& error,
  std::vector<std::string>& warnings)
{
  vtkDataArray* array = input->GetPointData()->GetArray(name.c_str());
  if (!array)
  {
    error = std::string("the ") + what + " array '" + name +
      "' is not a numeric point array of the input";
    return false;
  }
  const vtkIdType numPoints = input->GetNumberOfPoints();
  if (array->GetNumberOfTuples() < numPoints)
  {
    error = std::string("the ") + what + " array '" + name + "' has " +
      std::to_string(array->GetNumberOfTuples()) + " tuples for " + std::to_string(numPoints) +
      " points";
    return false;
  }
  const int nc = array->GetNumberOfComponents();
  int c = nc == 1 ? 0 : component;
  if (c >= nc || c < -1)
  {
    c = std::min(std::max(c, 0), nc - 1);
    warnings.push_back(std::string("component ") + std::to_string(component) + " of the " + what +
      " array '" + name + "' is out of range; using " + std::to_string(c));
  }
  if (cache.Array == array && cache.ArrayTime == array->GetMTime() &&
    cache.InputTime == input->GetMTime() && cache.Component == c)
  {
    return true;
  }
  cache.Array = array;
  cache.ArrayTime = array->GetMTime();
  cache.InputTime = input->GetMTime();
  cache.Component = c;
  cache.Values.resize(numPoints);
  std::vector<double> tuple(nc);
  vtkIdType bad = 0;
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    double v = 0.0;
    if (c >= 0)
    {
      v = array->GetComponent(i, c);
    }
    else
    {
      array->GetTuple(i, tuple.data());
      for (double x : tuple)
      {
        v += x * x;
      }
      v = std::sqrt(v);
    }
    if (!std::isfinite(v))
    {
      v = 0.0;
      ++bad;
    }
    cache.Values[i] = v;
  }
  if (bad)
  {
    warnings.push_back(std::to_string(bad) + " NaN/Inf values of the " + what + " array '" + name +
      "' are taken as 0");
  }
  return true;
}

void hov::FeatureSetup::PrepareLights(vtkRenderer* renderer, vtkCamera* camera, vtkVolume* volume)
{
  hov::Features& f = this->Features;
  bool singleHeadlight = false;
  double ambient[3];
  hov::ReadLights(renderer, camera, f.Lights, f.Material.TwoSidedLighting, singleHeadlight, ambient);
  vtkVolumeProperty* property = volume->GetProperty();
  if (property->GetShade(0))
  {
    f.Material.Ambient = property->GetAmbient(0);
    f.Material.Diffuse = property->GetDiffuse(0);
    f.Material.Specular = property->GetSpecular(0);
    f.Material.SpecularPower = property->GetSpecularPower(0);
  }
  else
  {
    f.Material.Ambient = 1.0;
    f.Material.Diffuse = 0.0;
    f.Material.Specular = 0.0;
  }
  // Points to world; gradients (covectors) with the inverse transpose.
  vtkMatrix4x4* m = volume->GetMatrix();
  glm::dmat4 toWorld(1.0);
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      toWorld[j][i] = m->GetElement(i, j);
    }
  }
  f.DataToWorld = toWorld;
  f.NormalToWorld = glm::transpose(glm::inverse(glm::dmat3(toWorld)));
}

bool hov::FeatureSetup::Prepare(const Options& options, vtkUnstructuredGridBase* input,
  vtkRenderer* renderer, vtkCamera* camera, vtkVolume* volume, std::string& error,
  std::vector<std::string>& warnings)
{
  hov::Features& f = this->Features;
  f.Surfaces = options.Surfaces;
  f.IsoValues.clear();
  for (const hov::Isosurface& s : f.Surfaces)
  {
    f.IsoValues.push_back(s.Value);
  }
  f.Splatting = options.Splatting;
  f.SplatPixelThreshold = options.SplatPixelThreshold;
  f.ColorField = nullptr;
  f.IsoField = nullptr;
  if (!options.ColorArray.empty())
  {
    if (!this->PrepareField(options.ColorArray, options.ColorComponent, "colour", input, this->Color,
          error, warnings))
    {
      return false;
    }
    f.ColorField = &this->Color.Values;
  }
  if (!options.IsoArray.empty())
  {
    if (!this->PrepareField(
          options.IsoArray, options.IsoComponent, "isosurface", input, this->Iso, error, warnings))
    {
      return false;
    }
    f.IsoField = &this->Iso.Values;
  }
  this->PrepareVolumeShading(options.Shading, warnings);
  if (f.Active())
  {
    this->PrepareLights(renderer, camera, volume);
  }
  return true;
}

void hov::FeatureSetup::PrepareVolumeShading(
  const hov::ShadingFrameSettings* shading, std::vector<std::string>& warnings)
{
  hov::Features& f = this->Features;
  f.VolumeShading = hov::VolumeShadingSettings();
  f.VolumeLights.clear();
  f.UseGradientOpacity = false;
  if (!shading || !shading->Active())
  {
    return;
  }
  if (shading->Shade)
  {
    f.VolumeLights = shading->Lights;
    f.VolumeShading.Shade = true;
    f.VolumeShading.Material = shading->Material;
    f.VolumeShading.Ambient = shading->Ambient;
    std::copy(shading->AmbientLight, shading->AmbientLight + 3, f.VolumeShading.AmbientLight);
    f.VolumeShading.Lights = f.VolumeLights.data();
    f.VolumeShading.LightCount = static_cast<int>(f.VolumeLights.size());
  }
  const std::vector<hov::OpacityNode>& nodes = shading->GradientOpacityNodes;
  const auto same = [](const hov::OpacityNode& a, const hov::OpacityNode& b) {
    return a.X == b.X && a.Opacity == b.Opacity;
  };
  if (shading->GradientOpacity && this->GradientOpacityNodes.size() == nodes.size() &&
    std::equal(nodes.begin(), nodes.end(), this->GradientOpacityNodes.begin(), same))
  {
    f.UseGradientOpacity = !f.GradientOpacity.IsIdentity(); // built for these nodes
  }
  else if (shading->GradientOpacity)
  {
    // Rebuilt (and its messages reported) only when the nodes change.
    this->GradientOpacityNodes = nodes;
    hov::GradientOpacitySpec spec;
    spec.Nodes = shading->GradientOpacityNodes;
    std::vector<std::string> messages;
    f.GradientOpacity.Build(spec, &messages);
    for (const std::string& m : messages)
    {
      warnings.push_back("Gradient opacity: " + m);
    }
    f.UseGradientOpacity = !f.GradientOpacity.IsIdentity();
  }
}
