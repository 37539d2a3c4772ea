// vtkHighOrderVolumeMapper's RAY_CAST render mode (issue 6): input
// conversion and caching, the transfer-function table, the interaction level
// of detail, and the error image. See the RenderMode doc in the header.
#include "vtkHighOrderVolumeMapper.h"

#include "hovRayCastBackend.h" // caster, cache keys, error image
#include "hovViewRays.h"     // pixel rays

#include "hovCurvedSegment.h"    // CurvedSegmentSettings
#include "hovTransferFunction.h" // the kernel table

#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkCommand.h" // ProgressEvent, AbortCheckEvent
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm> // std::min, std::max
#include <chrono>    // the interactive frame's time budget
#include <cmath>     // std::sqrt, std::ceil
#include <string>    // messages

namespace
{
void PublishError(vtkImageData* image, const std::vector<float>& error, int width, int height)
{
  image->SetDimensions(std::max(width, 0), std::max(height, 0), 1);
  vtkNew<vtkFloatArray> array;
  array->SetName("Error");
  array->SetNumberOfComponents(1);
  array->SetNumberOfTuples(static_cast<vtkIdType>(error.size()));
  std::copy(error.begin(), error.end(), array->GetPointer(0));
  image->GetPointData()->SetScalars(array);
}

/// Pixel (i of n) of the full image -> pixel of the reduced one (m <= n).
inline int Reduced(int i, int n, int m)
{
  return std::min(static_cast<int>(static_cast<long long>(i) * m / n), m - 1);
}
}

vtkImageData* vtkHighOrderVolumeMapper::GetRayCastErrorImage()
{
  return this->RayCastImpl->ErrorImage;
}

int vtkHighOrderVolumeMapper::ComputeRayCastImage(vtkCamera* camera, vtkVolume* volume, int width,
  int height, double aspect, const float* depth, std::vector<double>& rgba, bool& drawn)
{
  drawn = false;
  hov::RayCastState& st = *this->RayCastImpl;
  const size_t pixels = static_cast<size_t>(std::max(width, 0)) * std::max(height, 0);
  rgba.assign(4 * pixels, 0.0);
  st.Error.assign(pixels, 0.0f);
  this->WitnessViolations = this->NumberOfSegments = this->NumberOfPieces = 0;
  this->NumberOfRays = 0;
  this->NumberOfSplattedCells = this->NumberOfRenderedCells = this->NumberOfSkippedCells = 0;
  this->LastRenderWasInteractive = false;
  auto finish = [&](int status) {
    PublishError(st.ErrorImage, st.Error, width, height);
    return status;
  };
  if (!camera || !volume || width <= 0 || height <= 0)
  {
    vtkErrorMacro("RenderImage needs a camera, a volume and a positive size.");
    return finish(0);
  }
  if (!this->CheckFrameView(camera, volume, aspect))
  {
    return finish(0); // the error was reported
  }
  if (this->GetNumberOfInputConnections(0) > 0)
  {
    this->GetInputAlgorithm()->Update();
  }
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(this->GetInput());
  vtkVolumeProperty* property = volume->GetProperty();
  if (!grid || !property)
  {
    vtkErrorMacro("RAY_CAST needs a vtkUnstructuredGrid input and a vtkVolumeProperty.");
    return finish(0);
  }
  int cellFlag = 0;
  vtkDataArray* scalars = vtkAbstractMapper::GetScalars(
    grid, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
  if (!scalars || cellFlag != 0)
  {
    vtkErrorMacro("RAY_CAST needs numeric point scalars (set point scalars on the input or "
                  "select a numeric point array with SelectScalarArray()).");
    st.Valid = false;
    return finish(0);
  }
  const int nc = scalars->GetNumberOfComponents();
  const int component = nc == 1
    ? 0
    : (this->VectorMode == COMPONENT ? std::min(std::max(this->VectorComponent, 0), nc - 1) : -1);
  if (!st.Valid || st.InputTime != grid->GetMTime() || st.Array != scalars ||
    st.ArrayTime != scalars->GetMTime() || st.Component != component)
  {
    std::string message;
    const bool ok = st.Caster.SetInput(grid, scalars, component, &message);
    if (!message.empty())
    {
      vtkWarningMacro("RAY_CAST: skipped " << message << "; the rest is rendered.");
    }
    if (!ok)
    {
      vtkWarningMacro("RAY_CAST: no usable cell in the input (" << grid->GetNumberOfCells()
                                                                << " cells): nothing rendered.");
    }
    st.Valid = true; // cached also when nothing is usable: one warning per input
    st.InputTime = grid->GetMTime();
    st.Array = scalars;
    st.ArrayTime = scalars->GetMTime();
    st.Component = component;
  }
  const bool features = this->GetNumberOfIsosurfaces() > 0 || this->Splatting ||
    (this->ColorArrayName && *this->ColorArrayName) ||
    (this->IsosurfaceArrayName && *this->IsosurfaceArrayName);
  if (features && !st.FeatureWarned)
  {
    st.FeatureWarned = true;
    vtkWarningMacro("RAY_CAST does not apply isosurfaces, separate colour/isosurface fields or "
                    "splatting; they are ignored in this mode.");
  }
  this->NumberOfRenderedCells = st.Caster.GetNumberOfCells();
  this->NumberOfSkippedCells = grid->GetNumberOfCells() - this->NumberOfRenderedCells;

  vtkHighOrderTransferFunction* tf = st.TransferFunction;
  tf->SetOpacitySemantics(this->OpacitySemantics);
  // The table's linearisation error (<= 2x its tolerance) within a fifth of the
  // per-pixel tolerance: a finer table only adds breakpoints to locate.
  tf->SetGPUTolerance(std::max(this->GPUOpacityTolerance, 0.1 * this->RayCastTolerance));
  tf->SetEmissionScale(this->EmissionScale);
  tf->SetComponent(component > 0 && property->GetIndependentComponents() ? std::min(component, 3) : 0);
  const int buildsBefore = tf->GetBuildCount();
  tf->Update(property);
  for (int i = 0; tf->GetBuildCount() != buildsBefore && i < tf->GetNumberOfMessages(); ++i)
  {
    vtkWarningMacro("Transfer function: " << tf->GetMessage(i));
  }
  if (this->NumberOfRenderedCells == 0)
  {
    return finish(1); // nothing to render (warned above)
  }
  if (!tf->GetTable().HasExtinction() && this->EmissionModel != WILHELMS_VAN_GELDER)
  {
    if (tf->GetBuildCount() != buildsBefore)
    {
      this->WarnTransparent();
    }
    return finish(1); // nothing visible
  }

  // Interaction level of detail (see the RenderMode doc).
  vtkRenderWindow* window = this->FrameRenderer ? this->FrameRenderer->GetRenderWindow() : nullptr;
  const bool interactive =
    window && window->GetDesiredUpdateRate() >= this->RayCastInteractiveUpdateRate;
  this->LastRenderWasInteractive = interactive;
  int f = 1;
  if (interactive)
  {
    f = this->RayCastInteractiveSubsampling;
    if (f <= 0)
    {
      // The factor that fits the time budget at the last frame's cost per ray.
      const double budget = 1.0 / window->GetDesiredUpdateRate();
      const double cost = st.SecondsPerRay * width * height;
      f = st.SecondsPerRay > 0.0
        ? std::min(std::max(static_cast<int>(std::ceil(std::sqrt(cost / budget))), 2), 16)
        : 2;
    }
  }
  this->LastRayCastSubsampling = f;
  const int rw = (width + f - 1) / f, rh = (height + f - 1) / f;
  hov::ViewRays rays;
  if (!rays.Setup(camera, volume->GetMatrix(), rw, rh, aspect))
  {
    vtkErrorMacro("Singular camera or volume matrix: nothing rendered.");
    return finish(0);
  }
  rays.SetupClipping(
    this, camera, volume->GetMatrix(), this->ViewDepthClipping ? this->ViewDepthRange : nullptr);
  drawn = true;
  const float* rayDepth = depth;
  if (depth && interactive)
  {
    st.Depth.assign(static_cast<size_t>(rw) * rh, 1.0f);
    for (int j = 0; j < height; ++j)
    {
      for (int i = 0; i < width; ++i)
      {
        float& d = st.Depth[static_cast<size_t>(Reduced(j, height, rh)) * rw + Reduced(i, width, rw)];
        d = std::min(d, depth[static_cast<size_t>(j) * width + i]);
      }
    }
    rayDepth = st.Depth.data();
  }
  hov::CurvedSegmentSettings settings;
  settings.Quadrature.Emission = static_cast<hov::EmissionModel>(this->EmissionModel);
  settings.Quadrature.Tolerance =
    interactive ? std::min(10.0 * this->RayCastTolerance, 0.05) : this->RayCastTolerance;
  st.RGBA.assign(4 * static_cast<size_t>(rw) * rh, 0.0f);
  std::vector<float> error(static_cast<size_t>(rw) * rh, 0.0f);
  hov::RayCast::Issues issues;
  hov::ProgressFunction progress;
  if (this->HasObserver(vtkCommand::ProgressEvent) ||
    (window && window->HasObserver(vtkCommand::AbortCheckEvent)))
  {
    progress = [this](double done) { return this->ReportTileProgress(done); };
  }
  const auto start = std::chrono::steady_clock::now();
  st.Caster.Render(
    rays, tf->GetTable(), settings, st.RGBA.data(), error.data(), rayDepth, &issues, progress);
  if (!issues.Aborted && rw * rh > 0)
  {
    st.SecondsPerRay =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / (rw * rh);
  }
  this->LastRenderAborted = issues.Aborted;
  this->NumberOfRays = issues.Rays;
  this->NumberOfSegments = issues.Segments;
  this->NumberOfPieces = issues.Segments + issues.Breakpoints;
  if (issues.NotConverged > 0 || issues.NotFinite > 0)
  {
    vtkWarningMacro("RAY_CAST: " << issues.NotConverged << " of " << rw * rh
                                 << " pixels did not converge to the tolerance (Newton inversion "
                                    "or quadrature; see GetRayCastErrorImage() for how far), "
                                 << issues.NotFinite
                                 << " had a non-finite colour and are drawn transparent.");
  }
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
        rgba[4 * p + c] = st.RGBA[4 * q + c];
      }
      st.Error[p] = error[q];
    }
  }
  return finish(1);
}
