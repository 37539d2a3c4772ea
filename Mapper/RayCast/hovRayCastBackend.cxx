#include "hovRayCastBackend.h"

#include "hovBlendCheck.h"   // BlendSettingsOf
#include "hovCellSetup.h"    // ShortScalars
#include "hovFloatImage.h"   // the error image
#include "hovReducedImage.h" // interactive frames
#include "hovViewRays.h"     // pixel rays

#include "hovCurvedSegment.h"    // CurvedSegmentSettings
#include "hovTransferFunction.h" // the kernel table

#include "vtkUnstructuredGrid.h" // the input
#include "vtkVolume.h"           // the property

#include <algorithm> // std::min, std::max
#include <chrono>    // the fixed part of the frame's cost
#include <sstream>   // messages
#include <string>    // messages

int hov::RayCastBackend::Render(RenderFrame& frame, vtkImageData*)
{
  frame.ClearImage();
  const size_t pixels = frame.ImagePixels(); // 0 for a size Trace() refuses
  this->Error.assign(pixels, 0.0f);
  const int status = this->Trace(frame);
  PublishFloatImage(this->ErrorImage, "Error", 1, pixels ? frame.Width : 0,
    pixels ? frame.Height : 0, this->Error.data());
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
    frame.Warning("RAY_CAST: skipped " + message + (ok ? "; the rest is rendered." : "."));
  }
  if (!ok)
  {
    std::ostringstream text;
    text << "RAY_CAST: no usable cell in the input (" << grid->GetNumberOfCells()
         << " cells): nothing rendered.";
    frame.Warning(text.str());
  }
  frame.InputReported = true;
  this->InvisibleValid = false; // a new caster: its cells' flags are computed again
  this->Valid = true; // cached also when nothing is usable: one warning per input
  this->Key = key;
  this->Skipped = ok ? grid->GetNumberOfCells() - this->Caster.GetNumberOfCells() : -1;
}

int hov::RayCastBackend::Trace(RenderFrame& frame)
{
  const auto begin = std::chrono::steady_clock::now();
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
  // As CPU_ACCURATE (the same check and message): an error, not a skip.
  const std::string shortArray =
    CellSetup::ShortScalars(grid, frame.Scalars.Array, frame.Scalars.CellScalars);
  if (!shortArray.empty())
  {
    frame.Error("Cannot render: " + shortArray + ".");
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
  // 10^5 nodes (hovBackend.h; hovRobustness seed 7, case 7040481).
  this->TransferFunction->SetRefinementBudget(RayCastTableBudget);
  const bool visible = frame.UpdateTransferFunction(this->TransferFunction,
    std::max(s.GPUOpacityTolerance, 0.1 * s.RayCastTolerance), rebuilt);
  if (rebuilt)
  {
    this->InvisibleValid = false; // a new table: the invisible cells change
  }
  if (frame.Stats.RenderedCells == 0)
  {
    frame.NoRenderedCell(grid->GetNumberOfCells()); // (warned when the caster was built)
    return 1;
  }
  if (!visible && s.Blend != BlendMode::AverageIntensity) // average: grey even without opacity
  {
    frame.NoVisibleVolume(rebuilt);
    return 1; // nothing visible
  }

  // Interactive frames (the facade's choice, hovInteractionBudget.h): one ray
  // per f x f block, each stopping at the nearest opaque depth of its block.
  const bool interactive = frame.Interactive;
  const int f = std::max(frame.Subsampling, 1);
  const int width = frame.Width, height = frame.Height;
  const int rw = ReducedSize(width, f), rh = ReducedSize(height, f);
  ViewRays rays;
  if (!frame.SetupRays(rays, rw, rh))
  {
    return 0;
  }
  frame.Drawn = true;
  const float* rayDepth = frame.Depth;
  if (frame.Depth && f > 1)
  {
    ReduceDepth(frame.Depth, width, height, rw, rh, this->Depth);
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
  frame.Stats.FixedSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  const BlendSettings blend = BlendSettingsOf(frame);
  const bool blending = blend.Mode != BlendMode::Composite;
  // Cells whose whole field hull is invisible compute no interval (composite
  // rays, shaded ones only under Williams-Max; SkipTransparentCells). The flags follow the table and the
  // caster: recomputed when either was rebuilt or the emission model changed.
  const bool shaded = (settings.Shading && settings.Shading->Shade) || settings.GradientOpacity;
  const bool skip = s.SkipTransparentCells && !blending &&
    (!shaded || s.Emission == EmissionModel::WilliamsMax);
  if (skip && (!this->InvisibleValid || this->InvisibleEmission != s.Emission))
  {
    this->InvisibleCount = this->Caster.MarkInvisibleCells(
      this->TransferFunction->GetTable(), s.Emission, this->Invisible);
    this->InvisibleValid = true;
    this->InvisibleEmission = s.Emission;
  }
  frame.Stats.TransparentCells = skip ? this->InvisibleCount : 0;
  this->Caster.Render(rays,
    blending ? this->TransferFunction->GetBlendTable() : this->TransferFunction->GetTable(),
    settings, this->RGBA.data(), error.data(), rayDepth, &issues, frame.Progress,
    blending ? &blend : nullptr, skip && this->InvisibleCount > 0 ? &this->Invisible : nullptr);
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
  ExpandImage(this->RGBA.data(), rw, rh, 4, frame.RGBA.data(), width, height);
  ExpandImage(error.data(), rw, rh, 1, this->Error.data(), width, height);
  return 1;
}
