// vtkHighOrderVolumeMapper: isosurfaces, separate colour/isosurface fields
// and subpixel splatting (the settings and their per-frame preparation; the
// rendering is hov::FeatureProjector). Kept apart from the mapper's
// main file.
#include "vtkHighOrderVolumeMapper.h"

#include "hovFeatureSetup.h" // arrays, lights, the feature projector

#include "vtkUnstructuredGridBase.h"

#include <algorithm> // std::min, std::max
#include <cmath>     // std::isfinite
#include <string>    // messages
#include <vector> // messages

int vtkHighOrderVolumeMapper::AddIsosurface(
  double value, double r, double g, double b, double opacity)
{
  this->Isosurfaces.insert(this->Isosurfaces.end(), { value, r, g, b, opacity });
  this->Modified();
  return static_cast<int>(this->Isosurfaces.size() / 5) - 1;
}

void vtkHighOrderVolumeMapper::RemoveAllIsosurfaces()
{
  if (!this->Isosurfaces.empty())
  {
    this->Isosurfaces.clear();
    this->Modified();
  }
}

int vtkHighOrderVolumeMapper::GetNumberOfIsosurfaces()
{
  return static_cast<int>(this->Isosurfaces.size() / 5);
}

double vtkHighOrderVolumeMapper::GetIsosurfaceValue(int i)
{
  return i >= 0 && i < this->GetNumberOfIsosurfaces() ? this->Isosurfaces[5 * i] : 0.0;
}

int vtkHighOrderVolumeMapper::PrepareFeatures(vtkCamera* camera, vtkVolume* volume)
{
  hov::FeatureSetup::Options options;
  const int n = this->GetNumberOfIsosurfaces();
  int dropped = 0;
  for (int i = 0; i < n; ++i)
  {
    const double* v = &this->Isosurfaces[5 * i];
    hov::Isosurface s;
    s.Value = v[0];
    for (int k = 0; k < 3; ++k)
    {
      s.Color[k] = std::min(std::max(v[1 + k], 0.0), 1.0); // NaN -> 0
    }
    s.Opacity = std::min(std::max(v[4], 0.0), 1.0);
    if (!std::isfinite(s.Value))
    {
      ++dropped;
      continue;
    }
    options.Surfaces.push_back(s);
  }
  if (dropped)
  {
    vtkWarningMacro(<< dropped << " isosurfaces with a NaN/Inf value are ignored.");
  }
  options.ColorArray = this->ColorArrayName ? this->ColorArrayName : "";
  options.ColorComponent = this->ColorArrayComponent;
  options.IsoArray = this->IsosurfaceArrayName ? this->IsosurfaceArrayName : "";
  options.IsoComponent = this->IsosurfaceArrayComponent;
  options.Splatting = this->Splatting;
  options.SplatPixelThreshold = this->SplatPixelThreshold;
  std::string error;
  std::vector<std::string> warnings;
  const bool ok = this->FeatureImpl->Prepare(
    options, this->GetInput(), this->FrameRenderer, camera, volume, error, warnings);
  for (const std::string& w : warnings)
  {
    vtkWarningMacro(<< w << ".");
  }
  if (!ok)
  {
    vtkErrorMacro("Cannot render: " << error << ".");
    return -1;
  }
  return this->FeatureImpl->GetFeatures().Active() ? 1 : 0;
}
