#include "hovRayCastBackend.h"

#include "hovBlendCheck.h" // BlendSettingsOf
#include "hovFloatImage.h" // the error image
#include "hovViewRays.h"   // pixel rays

#include "hovCurvedSegment.h"    // CurvedSegmentSettings
#include "hovTransferFunction.h" // the kernel table

#include "vtkRenderWindow.h"     // interaction level of detail
#include "vtkRenderer.h"         // its window
#include "vtkUnstructuredGrid.h" // the input
#include "vtkVolume.h"           // the property

#include <algorithm> // std::min, std::max
#include <chrono>    // the interactive frame's time budget
#include <cmath>     // std::sqrt, std::ceil
#include <sstream>   // messages
#include <string>    // messages

namespace
{
/// Most nodes the ray caster's GPU-compatible table may add (see its use).
constexpr int RayCastTableBudget = 16384;
/// Pixel (i of n) of the full image -> pixel of the reduced one (m <= n).
inline int Reduced(int i, int n, int m)
{
  return std::min(static_cast<int>(static_cast<long long>(i) * m / n), m - 1);
}
}

int hov::RayCastBackend::Render(RenderFrame& frame, vtkImageData*)
{
  frame.ClearImage();
  this->Error.assign(static_cast<size_t>(std::max(frame.Width, 0)) * std::max(frame.Height, 0), 0.0f);
  frame.Stats.Interactive = 0;
  const int status = this->Trace(frame);
  PublishFloatImage(this->ErrorImage, "Error", 1, frame.Width, frame.Height, this->Error.data());
  return status;
}

void hov::RayCastBackend::PrepareCaster(const RenderFrame& frame, vtkUnstructuredGrid* grid)
{
  const InputKey key = frame.Key();
  if (this->Valid && key == this->Key)
  {
    return;
  }
  std::string message;
  const bool ok =
    this->Caster.SetInput(grid, frame.Scalars.Array, frame.Scalars.Component,
      frame.Scalars.CellScalars, &message);
  if (!message.empty())
  {
    frame.Warning("RAY_CAST: skipped " + message + "; the rest is rendered.");
  }
  if (!ok)
  {
    std::ostringstream text;
    text << "RAY_CAST: no usable cell in the input (" << grid->GetNumberOfCells()
         << " cells): nothing rendered.";
    frame.Warning(text.str());
  }
  this->Valid = true; // cached also when nothing is usable: one warning per input
  this->Key = key;
}

int hov::RayCastBackend::Subsampling(const RenderFrame& frame, double desiredUpdateRate) const
{
  int f = frame.Settings.RayCastInteractiveSubsampling;
  if (f <= 0)
  {
    // The factor that fits the time budget at the last frame's cost per ray.
    const double budget = 1.0 / desiredUpdateRate;
    const double cost = this->SecondsPerRay * frame.Width * frame.Height;
    f = this->SecondsPerRay > 0.0
      ? std::min(std::max(static_cast<int>(std::ceil(std::sqrt(cost / budget))), 2), 16)
      : 2;
  }
  return f;
}

int hov::RayCastBackend::Trace(RenderFrame& frame)
{
  if (!frame.ValidateView())
  {
    return 0;
  }
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(frame.Input);
  if (!grid || !frame.Volume->GetProperty())
  {
    frame.Error("RAY_CAST needs a vtkUnstructuredGrid input and a vtkVolumeProperty.");
    return 0;
  }
  if (!frame.Scalars.Array || (frame.Scalars.Association != 0 && !frame.Scalars.CellScalars))
  {
    frame.Error("RAY_CAST needs numeric point or cell scalars (set scalars on the input or "
                "select a numeric array with SelectScalarArray()).");
    this->Valid = false;
    return 0;
  }
  this->PrepareCaster(frame, grid);
  const FrameSettings& s = frame.Settings;
  // (With a blend mode hov::BlendCheck has warned already.)
  const bool features = s.Blend == BlendMode::Composite &&
    (s.NumberOfIsosurfaces() > 0 || s.Splatting || !s.ColorArray.empty() ||
      !s.IsosurfaceArray.empty());
  if (features && !this->FeatureWarned)
  {
    this->FeatureWarned = true;
    frame.Warning("RAY_CAST does not apply isosurfaces, separate colour/isosurface fields or "
                  "splatting; they are ignored in this mode.");
  }
  frame.Stats.RenderedCells = this->Caster.GetNumberOfCells();
  frame.Stats.SkippedCells = grid->GetNumberOfCells() - frame.Stats.RenderedCells;
  bool rebuilt = false;
  // Every node in a segment's scalar range is a breakpoint to locate on that
  // segment: a budget keeps a frame finite where the tolerance would need
  // 10^5 nodes (opacity 1 at a node is a log singularity of the extinction;
  // GPUOpacityTolerance 1e-8 there): the table then stops at its budget and
  // says so, with its worst error (hovRobustness seed 7, case 7040481).
  this->TransferFunction->SetRefinementBudget(RayCastTableBudget);
  const bool visible = frame.UpdateTransferFunction(this->TransferFunction,
    std::max(s.GPUOpacityTolerance, 0.1 * s.RayCastTolerance), rebuilt);
  if (frame.Stats.RenderedCells == 0)
  {
    return 1; // nothing to render (warned above)
  }
  if (!visible && s.Blend != BlendMode::AverageIntensity) // average: grey even without opacity
  {
    if (rebuilt)
    {
      frame.WarnTransparent();
    }
    return 1; // nothing visible
  }

  // Interaction level of detail (see the RenderMode doc).
  vtkRenderWindow* window = frame.Renderer ? frame.Renderer->GetRenderWindow() : nullptr;
  const bool interactive =
    window && window->GetDesiredUpdateRate() >= s.RayCastInteractiveUpdateRate;
  frame.Stats.Interactive = interactive ? 1 : 0;
  const int f = interactive ? this->Subsampling(frame, window->GetDesiredUpdateRate()) : 1;
  frame.Stats.RayCastSubsampling = f;
  const int width = frame.Width, height = frame.Height;
  const int rw = (width + f - 1) / f, rh = (height + f - 1) / f;
  ViewRays rays;
  if (!frame.SetupRays(rays, rw, rh))
  {
    return 0;
  }
  frame.Drawn = true;
  const float* rayDepth = frame.Depth;
  if (frame.Depth && interactive)
  {
    // Each ray stops at the nearest opaque depth of its block.
    this->Depth.assign(static_cast<size_t>(rw) * rh, 1.0f);
    for (int j = 0; j < height; ++j)
    {
      for (int i = 0; i < width; ++i)
      {
        float& d = this->Depth[static_cast<size_t>(Reduced(j, height, rh)) * rw + Reduced(i, width, rw)];
        d = std::min(d, frame.Depth[static_cast<size_t>(j) * width + i]);
      }
    }
    rayDepth = this->Depth.data();
  }
  CurvedSegmentSettings settings;
  settings.Quadrature.Emission = s.Emission;
  settings.Quadrature.Tolerance =
    interactive ? std::min(10.0 * s.RayCastTolerance, 0.05) : s.RayCastTolerance;
  settings.TerminationTransmittance = s.TerminationTransmittance;
  this->Shading.Prepare(frame, settings);
  this->RGBA.assign(4 * static_cast<size_t>(rw) * rh, 0.0f);
  std::vector<float> error(static_cast<size_t>(rw) * rh, 0.0f);
  RayCast::Issues issues;
  const auto start = std::chrono::steady_clock::now();
  const BlendSettings blend = BlendSettingsOf(frame);
  const bool blending = blend.Mode != BlendMode::Composite;
  this->Caster.Render(rays,
    blending ? this->TransferFunction->GetBlendTable() : this->TransferFunction->GetTable(),
    settings, this->RGBA.data(), error.data(), rayDepth, &issues, frame.Progress,
    blending ? &blend : nullptr);
  if (!issues.Aborted && rw * rh > 0)
  {
    this->SecondsPerRay =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / (rw * rh);
  }
  frame.Stats.Aborted = issues.Aborted;
  frame.Stats.Rays = issues.Rays;
  frame.Stats.Segments = issues.Segments;
  frame.Stats.Pieces = issues.Segments + issues.Breakpoints;
  if (issues.NotConverged > 0 || issues.NotFinite > 0)
  {
    std::ostringstream text;
    text << "RAY_CAST: " << issues.NotConverged << " of " << rw * rh
         << " pixels did not converge to the tolerance (Newton inversion or quadrature; see "
            "GetRayCastErrorImage() for how far), "
         << issues.NotFinite << " had a non-finite colour and are drawn transparent.";
    frame.Warning(text.str());
  }
  // The (reduced) image onto every pixel.
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      const size_t p = static_cast<size_t>(j) * width + i;
      const size_t q = interactive
        ? static_cast<size_t>(Reduced(j, height, rh)) * rw + Reduced(i, width, rw)
        : p;
      for (int c = 0; c < 4; ++c)
      {
        frame.RGBA[4 * p + c] = this->RGBA[4 * q + c];
      }
      this->Error[p] = error[q];
    }
  }
  return 1;
}
