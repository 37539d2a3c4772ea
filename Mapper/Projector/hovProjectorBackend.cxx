#include "hovProjectorBackend.h"

#include "hovBlendCheck.h"    // BlendSettingsOf
#include "hovCellScene.h"    // cells, order, table
#include "hovReducedImage.h" // interactive frames
#include "hovRenderFrame.h"  // the frame
#include "hovViewRays.h"     // pixel rays

#include "hovIsosurface.h"       // Isosurface
#include "hovTransferFunction.h" // the table

#include "vtkVolume.h" // the property

#include <algorithm> // std::min, std::max
#include <chrono>    // the fixed part of the frame's cost
#include <cmath>     // std::isfinite
#include <string>    // messages
#include <vector>    // messages

int hov::ProjectorBackend::Render(RenderFrame& frame, vtkImageData*)
{
  const auto begin = std::chrono::steady_clock::now();
  CellScene& scene = this->Scene;
  bool ok = frame.ValidateView() && scene.Prepare(frame);
  // Isosurfaces are visible even where the volume does not absorb.
  bool render = ok && scene.GetCells().GetNumberOfRenderedCells() > 0;
  if (ok && !render)
  {
    frame.NoRenderedCell(frame.Stats.RenderedCells + frame.Stats.SkippedCells);
  }
  bool rebuilt = false;
  vtkHighOrderTransferFunction* tf = scene.GetTransferFunction();
  const bool blend = frame.Settings.Blend != BlendMode::Composite;
  // Non-tetrahedral cells integrate every table interval a segment crosses
  // by quadrature: their frames take the budget of hovBackend.h; tetrahedra
  // (closed forms) the table's own limit.
  tf->SetRefinementBudget(scene.GetCells().GetGeneralCells().GetCells().empty()
      ? TransferFunction::MaxRefinementNodes
      : QuadratureTableBudget);
  // Average intensity is opaque grey wherever the ray meets the range, even
  // with no opacity; the other blend modes draw no features.
  if (render &&
    !frame.UpdateTransferFunction(tf, frame.Settings.GPUOpacityTolerance, rebuilt) &&
    (blend || frame.Settings.NumberOfIsosurfaces() == 0) &&
    frame.Settings.Blend != BlendMode::AverageIntensity)
  {
    frame.NoVisibleVolume(rebuilt);
    render = false;
  }
  // An interactive frame: one exact ray per f x f block (hovReducedImage.h).
  const int f = std::max(frame.Subsampling, 1);
  const int rw = ReducedSize(frame.Width, f), rh = ReducedSize(frame.Height, f);
  ViewRays rays;
  if (render && !frame.SetupRays(rays, rw, rh))
  {
    render = ok = false;
  }
  // Every path below renders the rw x rh rays into `image` with `depth` (for
  // f > 1: the reduced image with the nearest opaque depth of each block) and
  // then calls expand() (the reduced image onto every pixel of its block).
  const float* depth = frame.Depth;
  if (render && depth && f > 1)
  {
    ReduceDepth(frame.Depth, frame.Width, frame.Height, rw, rh, this->Depth);
    depth = this->Depth.data();
  }
  std::vector<double>& image = f > 1 ? this->Reduced : frame.RGBA;
  auto expand = [&]() {
    if (f > 1)
    {
      frame.ClearImage();
      ExpandImage(this->Reduced.data(), rw, rh, 4, frame.RGBA.data(), frame.Width, frame.Height);
    }
    frame.Stats.Rays = static_cast<vtkIdType>(rw) * rh;
  };
  if (render && blend)
  {
    // No order needed: max, min and sums commute (hov::BlendProjector).
    ProjectorSettings settings;
    settings.TileSize = frame.Settings.TileSize;
    settings.Progress = frame.Progress;
    const ProjectorStatistics st = this->Blend.Render(scene.GetCells(), rays,
      tf->GetBlendTable(), BlendSettingsOf(frame), settings, depth, image);
    expand();
    frame.Drawn = true;
    frame.Stats.Aborted = st.Aborted;
    frame.Stats.Segments = st.Segments;
    frame.Stats.Pieces = st.Pieces;
    return 1;
  }
  if (render && !scene.PrepareOrder(frame, false))
  {
    render = ok = false; // an error (no visibility sort): status 0, no empty-image warning
  }
  frame.Drawn = render;
  if (!render)
  {
    frame.ClearImage();
    return ok ? 1 : 0;
  }
  // The projector sizes the image and writes every pixel: no clearing.
  CellProjector::Settings settings;
  settings.Integration.Emission = frame.Settings.Emission;
  settings.Integration.Method = frame.Settings.Integration;
  settings.TerminationTransmittance = frame.Settings.TerminationTransmittance;
  // A cyclic order cannot be exact: fall back to the per-pixel order.
  settings.PerPixelSort =
    frame.Settings.Ordering == CellOrdering::PerPixelSort || scene.OrderHasCycles();
  settings.TileSize = frame.Settings.TileSize;
  settings.RecordBudget = static_cast<size_t>(std::max(frame.Settings.CellRecordMemory, 0)) << 20;
  // Segments without extinction are exactly zero only where emission needs extinction.
  settings.SkipTransparent =
    frame.Settings.SkipTransparentCells && frame.Settings.Emission == EmissionModel::WilliamsMax;
  settings.Progress = frame.Progress;
  const int features = this->PrepareFeatures(frame);
  frame.Stats.FixedSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  CellProjector::Statistics st;
  if (features > 0) // isosurfaces, separate fields or splatting: the feature path
  {
    st = this->Features.GetProjector().Render(scene.GetCells(), scene.GetFrontToBack(), rays,
      tf->GetTable(), settings, this->Features.GetFeatures(), depth, image);
    frame.Stats.SplattedCells = this->Features.GetProjector().GetNumberOfSplats();
  }
  else if (features == 0)
  {
    st = this->Projector.Render(
      scene.GetCells(), scene.GetFrontToBack(), rays, tf->GetTable(), settings, depth, image);
    if (f == 1)
    {
      frame.Content = st.Content; // (reduced frames keep the default: the whole image)
    }
  }
  if (features >= 0)
  {
    expand();
  }
  else
  {
    // A missing or short colour/isosurface array: reported as an error.
    frame.ClearImage();
    frame.Stats.Rays = static_cast<vtkIdType>(rw) * rh;
    frame.Drawn = ok = false;
  }
  frame.Stats.Aborted = st.Aborted;
  frame.Stats.WitnessViolations = st.WitnessViolations;
  frame.Stats.Segments = st.Segments;
  frame.Stats.Pieces = st.Pieces;
  frame.Stats.CellRecords = st.Records;
  frame.Stats.TransparentCells = st.TransparentCells;
  frame.Stats.ShadingErrorEstimate = st.ShadingErrorEstimate;
  return ok ? 1 : 0;
}

int hov::ProjectorBackend::PrepareFeatures(const RenderFrame& frame)
{
  const FrameSettings& s = frame.Settings;
  FeatureSetup::Options options;
  int dropped = 0;
  for (int i = 0; i < s.NumberOfIsosurfaces(); ++i)
  {
    const double* v = &s.Isosurfaces[5 * i];
    Isosurface surface;
    surface.Value = v[0];
    for (int k = 0; k < 3; ++k)
    {
      surface.Color[k] = std::min(std::max(v[1 + k], 0.0), 1.0); // NaN stays (kernels clamp)
    }
    surface.Opacity = std::min(std::max(v[4], 0.0), 1.0);
    if (!std::isfinite(surface.Value))
    {
      ++dropped;
      continue;
    }
    options.Surfaces.push_back(surface);
  }
  if (dropped)
  {
    frame.Warning(std::to_string(dropped) + " isosurfaces with a NaN/Inf value are ignored.");
  }
  options.ColorArray = s.ColorArray;
  options.ColorComponent = s.ColorComponent;
  options.IsoArray = s.IsosurfaceArray;
  options.IsoComponent = s.IsosurfaceComponent;
  options.Splatting = s.Splatting;
  options.SplatPixelThreshold = s.SplatPixelThreshold;
  options.Shading = &s.Shading;
  std::string error;
  std::vector<std::string> warnings;
  const bool ok = this->Features.Prepare(
    options, frame.Input, frame.Renderer, frame.Camera, frame.Volume, error, warnings);
  for (const std::string& w : warnings)
  {
    frame.Warning(w + ".");
  }
  if (!ok)
  {
    frame.Error("Cannot render: " + error + ".");
    return -1;
  }
  return this->Features.GetFeatures().Active() ? 1 : 0;
}
