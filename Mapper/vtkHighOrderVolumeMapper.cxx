#include "vtkHighOrderVolumeMapper.h"

#include "hovBlendCheck.h"                // blend-mode warnings
#include "hovCellScene.h"                 // the cells the projection modes share
#include "hovFloatImage.h"                // the published image
#include "hovImageCheck.h"                // NaN/Inf pixels and empty images
#include "hovFrameLevel.h"                // the level of detail of a window frame
#include "hovImageDisplay.h"              // the CPU image over the scene, depth read-back
#include "hovInteractionBudget.h"         // interactive frames
#include "hovMapperEnums.h"               // the public enums as hov enums
#include "hovProgressiveStill.h"          // progressive still frames
#include "hovProjectionBackend.h"         // OPENGL_PROJECTION
#include "hovProjectorBackend.h"          // CPU_ACCURATE
#include "hovPropertyAudit.h"             // unhonoured property features
#include "hovRayCastBackend.h"            // RAY_CAST
#include "hovReducedImage.h"              // ReducedSize
#include "hovRenderFrame.h"               // the frame
#include "hovShadingSetup.h"              // shading, gradient opacity, lights
#include "vtkHighOrderTransferFunction.h" // GetTransferFunction
#include "vtkSteinVisibilitySort.h"       // the default (exact) visibility sort

#include "vtkCamera.h"        // the active camera
#include "vtkCommand.h"       // ProgressEvent, AbortCheckEvent
#include "vtkDoubleArray.h"   // GetDoubleImage
#include "vtkFloatArray.h"    // the float image
#include "vtkImageData.h"     // the float image
#include "vtkObjectFactory.h" // vtkStandardNewMacro
#include "vtkPlaneCollection.h" // clipping planes
#include "vtkPointData.h"     // the float image
#include "vtkRenderWindow.h"  // CheckAbortStatus
#include "vtkRenderer.h"      // viewport, depth
#include "vtkTimerLog.h"      // frame times
#include "vtkVolume.h"        // the volume

#include <algorithm> // std::copy
#include <cmath>     // std::isfinite
#include <sstream>   // messages
#include <string>    // messages

vtkStandardNewMacro(vtkHighOrderVolumeMapper);
vtkCxxSetObjectMacro(vtkHighOrderVolumeMapper, VisibilitySort, vtkVisibilitySort);
using namespace hov::mapper_enums; // Convert and the enum tables

namespace
{
/// The frame's messages as this mapper's warnings and errors.
class MapperMessages : public hov::FrameMessages
{
public:
  explicit MapperMessages(vtkHighOrderVolumeMapper* mapper)
    : Mapper(mapper)
  {
  }
  void Warning(const std::string& text) override
  {
    vtkWarningWithObjectMacro(this->Mapper, << text);
  }
  void Error(const std::string& text) override { vtkErrorWithObjectMacro(this->Mapper, << text); }

private:
  vtkHighOrderVolumeMapper* Mapper;
};
}

struct vtkHighOrderVolumeMapper::Internals
{
  explicit Internals(vtkHighOrderVolumeMapper* self)
    : Messages(self)
    , Projector(Scene)
    , Projection(Scene)
  {
  }
  MapperMessages Messages;
  hov::CellScene Scene; ///< cells, order and table of CPU_ACCURATE and OPENGL_PROJECTION
  hov::ProjectorBackend Projector;
  hov::ProjectionBackend Projection;
  hov::RayCastBackend RayCast;
  hov::ImageCheck Check;
  hov::BlendCheck Blend;
  hov::PropertyAudit Audit;
  hov::ShadingFrameSettings LastShading; ///< the last frame's (PrintSelf)
  hov::ImageDisplay Display;
  hov::InteractionBudget Budget;
  hov::ProgressiveStill Progressive;
  /// The render mode whose cost the frame measures (CPU_ACCURATE for an
  /// OPENGL_PROJECTION interactive frame drawn by the CPU path).
  int CostMode = 0;
  /// Seconds of the last frame that depend on its number of rays (the
  /// backend's time after its fixed part, hov::FrameStatistics::FixedSeconds).
  double LoopSeconds = 0.0;
  vtkNew<vtkImageData> FloatImage;
  std::vector<double> RGBA; ///< the last CPU image (GetDoubleImage)
  std::vector<float> Depth;
};

vtkHighOrderVolumeMapper::vtkHighOrderVolumeMapper()
  : Impl(new Internals(this))
{
  vtkSteinVisibilitySort* sort = vtkSteinVisibilitySort::New();
  this->SetVisibilitySort(sort);
  sort->Delete();
}

vtkHighOrderVolumeMapper::~vtkHighOrderVolumeMapper()
{
  this->SetVisibilitySort(nullptr);
  this->SetColorArrayName(nullptr);
  this->SetIsosurfaceArrayName(nullptr);
}

// ---- Settings -------------------------------------------------------------

namespace
{
/// Clamps @p value into [lo, hi] into @p field; false (nothing set) if not
/// finite; @p clamped if it was outside.
bool SetFiniteClamped(
  double& field, double value, double lo, double hi, bool& modified, bool& clamped)
{
  modified = clamped = false;
  if (!std::isfinite(value))
  {
    return false;
  }
  const double v = value < lo ? lo : (value > hi ? hi : value);
  clamped = v != value;
  modified = field != v;
  field = v;
  return true;
}
}

// The real-valued setters: like vtkSetClampMacro they clamp to the documented
// range (with a warning naming the setter, the value and the range), but a NaN
// (which vtkSetClampMacro lets through) or an infinity is refused with an error
// naming the setter, and the value stays.
#define HOV_FINITE_SETTER(name, lo, hi)                                                          \
  void vtkHighOrderVolumeMapper::Set##name(double value)                                         \
  {                                                                                              \
    bool modified = false, clamped = false;                                                      \
    if (!SetFiniteClamped(this->name, value, lo, hi, modified, clamped))                         \
    {                                                                                            \
      vtkErrorMacro(<< "Set" #name "(" << value << "): not a finite number; keeping "            \
                    << this->name);                                                              \
    }                                                                                            \
    else if (clamped)                                                                            \
    {                                                                                            \
      vtkWarningMacro(<< "Set" #name "(" << value << "): outside [" << lo << ", " << hi          \
                      << "]; clamped to " << this->name);                                        \
    }                                                                                            \
    if (modified)                                                                                \
    {                                                                                            \
      this->Modified();                                                                          \
    }                                                                                            \
  }

// Below 1e-8 the image error bound (2x) is beyond float's resolution, and the
// refined table only grows (1e-12: 10^6 nodes, every one a breakpoint).
HOV_FINITE_SETTER(GPUOpacityTolerance, 1e-8, 0.1)
HOV_FINITE_SETTER(TerminationTransmittance, 0.0, 0.1)
HOV_FINITE_SETTER(SplatPixelThreshold, 0.0, 1e6)
HOV_FINITE_SETTER(RayCastTolerance, 1e-12, 0.1)
HOV_FINITE_SETTER(RayCastInteractiveUpdateRate, 0.0, 1e6)
HOV_FINITE_SETTER(ProgressiveTime, 0.0, 1e6)
HOV_FINITE_SETTER(EmissionScale, 0.0, 1e6)

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

// ---- Outputs --------------------------------------------------------------

vtkImageData* vtkHighOrderVolumeMapper::GetFloatImage()
{
  return this->Impl->FloatImage;
}

void vtkHighOrderVolumeMapper::GetDoubleImage(vtkDoubleArray* rgba)
{
  if (!rgba)
  {
    return;
  }
  const std::vector<double>& values = this->Impl->RGBA;
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / 4));
  std::copy(values.begin(), values.end(), rgba->GetPointer(0));
}

vtkImageData* vtkHighOrderVolumeMapper::GetRayCastErrorImage()
{
  return this->Impl->RayCast.GetErrorImage();
}

vtkHighOrderTransferFunction* vtkHighOrderVolumeMapper::GetTransferFunction()
{
  return this->Impl->Scene.GetTransferFunction();
}

// ---- Rendering ------------------------------------------------------------

hov::Backend& vtkHighOrderVolumeMapper::SelectBackend(bool window)
{
  const bool blend = this->BlendMode > COMPOSITE_BLEND && this->BlendMode <= AVERAGE_INTENSITY_BLEND;
  switch (window ? this->Impl->CostMode : this->RenderMode)
  {
    case RAY_CAST:
      return this->Impl->RayCast;
    case OPENGL_PROJECTION:
      // Blend modes: the CPU kernels' image, shown by the image display.
      if (window && !blend)
      {
        return this->Impl->Projection;
      }
      return this->Impl->Projector; // RenderImage has no window: the CPU image
    default:
      return this->Impl->Projector;
  }
}

void vtkHighOrderVolumeMapper::InitFrame(hov::RenderFrame& frame, vtkCamera* camera,
  vtkVolume* volume, int width, int height, double aspect, vtkRenderer* renderer)
{
  frame.Camera = camera;
  frame.Volume = volume;
  frame.Renderer = renderer;
  frame.Mapper = this;
  frame.VisibilitySort = this->VisibilitySort;
  frame.Width = width;
  frame.Height = height;
  frame.Aspect = aspect;
  frame.Messages = &this->Impl->Messages;
  hov::FrameSettings& s = frame.Settings;
  s.Mode = Convert(RenderModes, this->RenderMode);
  s.Semantics = Convert(Semantics, this->OpacitySemantics);
  s.GPUOpacityTolerance = this->GPUOpacityTolerance;
  s.Emission = Convert(Emissions, this->EmissionModel);
  s.EmissionScale = this->EmissionScale;
  s.Integration = Convert(Methods, this->IntegrationMethod);
  s.Ordering = Convert(Orderings, this->CellOrdering);
  s.Vectors = Convert(VectorModes, this->VectorMode);
  s.VectorComponent = this->VectorComponent;
  s.TerminationTransmittance = this->TerminationTransmittance;
  s.TileSize = this->TileSize;
  s.CellRecordMemory = this->CellRecordMemory;
  s.SkipTransparentCells = this->SkipTransparentCells;
  s.UseDepthBuffer = this->UseDepthBuffer;
  s.ViewDepthClipping = this->ViewDepthClipping;
  s.ViewDepthRange[0] = this->ViewDepthRange[0];
  s.ViewDepthRange[1] = this->ViewDepthRange[1];
  s.HasClippingPlanes = this->ClippingPlanes && this->ClippingPlanes->GetNumberOfItems() > 0;
  // Unsupported blend modes render as composite (hov::BlendCheck warns).
  const bool blendKnown = this->BlendMode >= 0 && this->BlendMode <= AVERAGE_INTENSITY_BLEND;
  s.Blend = blendKnown ? BlendModes[this->BlendMode] : hov::BlendMode::Composite;
  s.AverageRange[0] = this->AverageIPScalarRange[0];
  s.AverageRange[1] = this->AverageIPScalarRange[1];
  s.RayCastTolerance = this->RayCastTolerance;
  s.ColorMethod = Convert(ColorMethods, this->ProjectionColorMethod);
  s.Order = Convert(Orders, this->ProjectionOrder);
  s.Lookup = Convert(Lookups, this->ProjectionOpacityLookup);
  s.Isosurfaces = this->Isosurfaces;
  s.ColorArray = this->ColorArrayName ? this->ColorArrayName : "";
  s.ColorComponent = this->ColorArrayComponent;
  s.IsosurfaceArray = this->IsosurfaceArrayName ? this->IsosurfaceArrayName : "";
  s.IsosurfaceComponent = this->IsosurfaceArrayComponent;
  s.Splatting = this->Splatting;
  s.SplatPixelThreshold = this->SplatPixelThreshold;
  this->Impl->Blend.Check(this->BlendMode, s, this->Impl->Messages);
  hov::ReadVolumeShading(volume, renderer, camera, this->BlendMode == COMPOSITE_BLEND, s.Shading);
  // Progress and abort between tile batches only with observers (the image is
  // the same either way).
  vtkRenderWindow* window = renderer ? renderer->GetRenderWindow() : nullptr;
  if (this->HasObserver(vtkCommand::ProgressEvent) ||
    (window && window->HasObserver(vtkCommand::AbortCheckEvent)))
  {
    frame.Progress = [this, renderer](double done) {
      return this->ReportTileProgress(renderer, done);
    };
  }
}

bool vtkHighOrderVolumeMapper::ReportTileProgress(vtkRenderer* renderer, double done)
{
  // Called on the rendering thread between tile batches (hovTileBatches.h).
  this->UpdateProgress(done);
  vtkRenderWindow* window = renderer ? renderer->GetRenderWindow() : nullptr;
  // A progressive level also stops for the UI's pending events (X windows).
  return this->AbortExecute || (window && window->CheckAbortStatus()) ||
    (window && this->Impl->Progressive.Active() && window->GetEventPending());
}

void vtkHighOrderVolumeMapper::ChooseLevel(hov::RenderFrame& frame, vtkRenderer* ren, vtkVolume* vol)
{
  Internals& impl = *this->Impl;
  hov::LevelSettings settings;
  settings.Mode = this->RenderMode;
  settings.Fixed = this->InteractiveSubsampling;
  settings.AutoAdjust = this->AutoAdjustImageSampleDistance;
  settings.ProgressiveTime = this->ProgressiveTime;
  settings.AfterInteraction = this->LastRenderWasInteractive;
  if (this->RenderMode == RAY_CAST)
  {
    frame.SelectInput(); // the key of the input the ray caster was built for
    settings.RayCastEveryCell = impl.RayCast.RendersEveryCell(frame.Key());
  }
  impl.CostMode =
    hov::ChooseFrameLevel(frame, settings, impl.Budget, impl.Progressive, ren, vol, this);
  if (impl.Progressive.Active() && !frame.Progress)
  {
    frame.Progress = [this, ren](double done) { return this->ReportTileProgress(ren, done); };
  }
}

bool vtkHighOrderVolumeMapper::FinishLevel(hov::RenderFrame& frame, double seconds)
{
  Internals& impl = *this->Impl;
  const int f = frame.Subsampling;
  this->LastRenderWasInteractive = frame.Interactive;
  this->LastSubsampling = f;
  this->LastDrawingMode = impl.CostMode;
  if (!this->LastRenderAborted)
  {
    // Everything but the backend's per-ray part is fixed: set-up, order, the
    // expansion of a reduced image, depth read-back and display.
    impl.Budget.Measure(impl.CostMode, seconds, seconds - std::max(impl.LoopSeconds, 0.0),
      static_cast<double>(hov::ReducedSize(frame.Width, f)) * hov::ReducedSize(frame.Height, f),
      f > 1);
  }
  auto* rgba = vtkFloatArray::SafeDownCast(impl.FloatImage->GetPointData()->GetScalars());
  const size_t pixels = static_cast<size_t>(frame.Width) * frame.Height;
  if (!rgba || static_cast<size_t>(rgba->GetNumberOfTuples()) != pixels)
  {
    return false;
  }
  const float* previous =
    impl.Progressive.Finished(this->LastRenderAborted, rgba->GetPointer(0), pixels);
  if (previous)
  {
    // An aborted exact level shows the last completed level.
    std::copy(previous, previous + 4 * pixels, rgba->GetPointer(0));
    rgba->Modified();
    return true;
  }
  return false;
}

void vtkHighOrderVolumeMapper::Publish(hov::RenderFrame& frame, float* windowPixels)
{
  const hov::FrameStatistics& st = frame.Stats;
  this->WitnessViolations = st.WitnessViolations;
  this->NumberOfRenderedCells = st.RenderedCells;
  this->NumberOfSkippedCells = st.SkippedCells;
  this->NumberOfSegments = st.Segments;
  this->NumberOfPieces = st.Pieces;
  this->NumberOfCellRecords = st.CellRecords;
  this->NumberOfTransparentCells = st.TransparentCells;
  this->NumberOfRays = st.Rays;
  this->NumberOfSplattedCells = st.SplattedCells;
  this->LastRenderAborted = st.Aborted;
  this->ShadingErrorEstimate = st.ShadingErrorEstimate;
  this->Impl->LastShading = frame.Settings.Shading;
  if (frame.Volume)
  {
    this->Impl->Audit.Check(frame, frame.Volume->GetProperty());
  }
  if (st.ProjectedTriangles >= 0)
  {
    this->NumberOfProjectedTriangles = st.ProjectedTriangles;
    this->NumberOfProjectedSlabs = st.ProjectedSlabs;
  }
  const size_t pixels = frame.ImagePixels(); // 0 for a size the frame refused
  if (windowPixels)
  {
    this->Impl->Check.Check(windowPixels, pixels, frame, this->GetMTime());
    return;
  }
  std::vector<double>& rgba = this->Impl->RGBA;
  rgba.swap(frame.RGBA);
  if (rgba.size() != 4 * pixels)
  {
    // Every backend writes the whole image (a reduced one expanded): a
    // mismatch is a defect, never shown as a garbled image.
    vtkErrorMacro("Internal error: the image has " << rgba.size() / 4 << " pixels for "
                                                  << frame.Width << " x " << frame.Height
                                                  << "; it is drawn transparent.");
    rgba.assign(4 * pixels, 0.0);
  }
  // Checked and converted to float in one parallel pass, into the published
  // array itself unless somebody else holds it.
  float* out = hov::FloatImagePixels(
    this->Impl->FloatImage, "RGBA", 4, pixels ? frame.Width : 0, pixels ? frame.Height : 0, true);
  this->Impl->Check.Check(rgba.data(), pixels, frame, this->GetMTime(), out);
}

int vtkHighOrderVolumeMapper::ComputeImage(hov::RenderFrame& frame, hov::Backend& backend)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  this->AbortExecute = 0; // a request to abort applies to one render
  this->LastRenderAborted = false;
  this->UpdateProgress(0.0);
  frame.RGBA.swap(this->Impl->RGBA); // reuse the last image's storage
  vtkNew<vtkTimerLog> backendTimer;
  backendTimer->StartTimer();
  const int status = backend.Render(frame, nullptr);
  backendTimer->StopTimer();
  this->Impl->LoopSeconds = backendTimer->GetElapsedTime() - frame.Stats.FixedSeconds;
  this->Publish(frame, nullptr);
  if (!this->LastRenderAborted && this->GetProgress() < 1.0)
  {
    this->UpdateProgress(1.0); // nothing to render, or no tile loop
  }
  timer->StopTimer();
  this->LastImageTime = timer->GetElapsedTime();
  return status;
}

int vtkHighOrderVolumeMapper::RenderImage(vtkCamera* camera, vtkVolume* volume, int width, int height)
{
  hov::RenderFrame frame;
  this->InitFrame(frame, camera, volume, width, height,
    height > 0 ? static_cast<double>(width) / height : 1.0, nullptr);
  this->Impl->CostMode = this->RenderMode;
  this->LastRenderWasInteractive = false; // no window, no budget: exact
  this->LastSubsampling = 1;
  this->LastDrawingMode = this->RenderMode;
  return this->ComputeImage(frame, this->SelectBackend(false));
}

void vtkHighOrderVolumeMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  int width = 0, height = 0, x0 = 0, y0 = 0;
  ren->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  if (width <= 0 || height <= 0)
  {
    return;
  }
  hov::RenderFrame frame;
  // The same aspect VTK's own mappers and actors use for the projection.
  this->InitFrame(frame, ren->GetActiveCamera(), vol, width, height, ren->GetTiledAspectRatio(), ren);
  frame.X0 = x0;
  frame.Y0 = y0;
  Internals& impl = *this->Impl;
  this->ChooseLevel(frame, ren, vol);
  hov::Backend& backend = this->SelectBackend(true);
  if (backend.DrawsIntoWindow())
  {
    // It reads the scene depth, draws and reads the float image back itself;
    // an aborted frame draws nothing (its last completed level is drawn here).
    this->AbortExecute = 0;
    this->LastRenderAborted = false;
    this->UpdateProgress(0.0);
    vtkNew<vtkTimerLog> backendTimer;
    backendTimer->StartTimer();
    backend.Render(frame, impl.FloatImage);
    backendTimer->StopTimer();
    if (!frame.Stats.Aborted)
    {
      this->UpdateProgress(1.0);
    }
    impl.LoopSeconds = backendTimer->GetElapsedTime() - frame.Stats.FixedSeconds;
    auto* rgba = vtkFloatArray::SafeDownCast(impl.FloatImage->GetPointData()->GetScalars());
    this->Publish(frame, rgba->GetPointer(0));
    timer->StopTimer();
    this->LastImageTime = this->TimeToDraw = timer->GetElapsedTime();
    if (this->FinishLevel(frame, this->TimeToDraw) &&
      !impl.Display.Draw(ren, rgba->GetPointer(0), width, height))
    {
      vtkErrorMacro("Could not draw the volume image with OpenGL.");
    }
    return;
  }
  if (this->UseDepthBuffer && hov::ImageDisplay::MayHoldDepth(ren))
  {
    impl.Depth.resize(static_cast<size_t>(width) * height);
    if (hov::ImageDisplay::ReadDepth(ren, width, height, x0, y0, impl.Depth.data()))
    {
      frame.Depth = impl.Depth.data();
    }
    else
    {
      vtkWarningMacro("Could not read the depth buffer; opaque geometry will not clip the volume.");
    }
  }
  this->ComputeImage(frame, backend);
  vtkNew<vtkTimerLog> tail;
  tail->StartTimer();
  timer->StopTimer();
  // The last completed level instead of an aborted one: drawn whole.
  const bool previous = this->FinishLevel(frame, timer->GetElapsedTime());
  vtkDataArray* rgba = impl.FloatImage->GetPointData()->GetScalars();
  if (rgba && rgba->GetNumberOfTuples() == static_cast<vtkIdType>(width) * height)
  {
    if (!impl.Display.Draw(ren, static_cast<vtkFloatArray*>(rgba)->GetPointer(0), width, height,
          previous ? nullptr : impl.Check.GetNonZeroBox()))
    {
      vtkErrorMacro("Could not draw the volume image with OpenGL.");
    }
  }
  tail->StopTimer();
  this->TimeToDraw = timer->GetElapsedTime() + tail->GetElapsedTime();
}

void vtkHighOrderVolumeMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Impl->Display.ReleaseGraphicsResources(win);
  this->Impl->Projection.ReleaseGraphicsResources(win);
  this->Superclass::ReleaseGraphicsResources(win);
}

void vtkHighOrderVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderMode: " << this->RenderMode << " (projection colour method "
     << this->ProjectionColorMethod << ", order " << this->ProjectionOrder << ", opacity lookup "
     << this->ProjectionOpacityLookup << ")\n";
  os << indent << "RayCastTolerance: " << this->RayCastTolerance
     << " (RayCastInteractiveUpdateRate, deprecated: " << this->RayCastInteractiveUpdateRate
     << ")\n";
  os << indent << "AutoAdjustImageSampleDistance: " << this->AutoAdjustImageSampleDistance
     << ", InteractiveSubsampling: " << this->InteractiveSubsampling
     << " (0: from the allocated render time; last frame " << this->LastSubsampling
     << (this->LastRenderWasInteractive ? ", interactive" : "") << ")\n";
  os << indent << "ProgressiveTime: " << this->ProgressiveTime << "\n";
  os << indent << "AverageIPScalarRange: " << this->AverageIPScalarRange[0] << " "
     << this->AverageIPScalarRange[1] << "\n";
  os << indent << "OpacitySemantics: " << this->OpacitySemantics << "\n";
  os << indent << "CellOrdering: " << this->CellOrdering << "\n";
  os << indent << "GPUOpacityTolerance: " << this->GPUOpacityTolerance << "\n";
  os << indent << "EmissionModel: " << this->EmissionModel << "\n";
  os << indent << "EmissionScale: " << this->EmissionScale << "\n";
  os << indent << "IntegrationMethod: " << this->IntegrationMethod << "\n";
  os << indent << "VectorMode: " << this->VectorMode << "\n";
  os << indent << "VectorComponent: " << this->VectorComponent << "\n";
  os << indent << "TerminationTransmittance: " << this->TerminationTransmittance << "\n";
  os << indent << "UseDepthBuffer: " << this->UseDepthBuffer << "\n";
  os << indent << "TileSize: " << this->TileSize << "\n";
  os << indent << "CellRecordMemory: " << this->CellRecordMemory << " MiB\n";
  os << indent << "SkipTransparentCells: " << this->SkipTransparentCells << "\n";
  os << indent << "ViewDepthClipping: " << this->ViewDepthClipping << " ["
     << this->ViewDepthRange[0] << ", " << this->ViewDepthRange[1] << "]\n";
  os << indent << "VisibilitySort: " << this->VisibilitySort << "\n";
  os << indent << "Isosurfaces: " << this->GetNumberOfIsosurfaces() << "\n";
  os << indent << "ColorArrayName: " << (this->ColorArrayName ? this->ColorArrayName : "(none)")
     << " component " << this->ColorArrayComponent << "\n";
  os << indent << "IsosurfaceArrayName: "
     << (this->IsosurfaceArrayName ? this->IsosurfaceArrayName : "(none)") << " component "
     << this->IsosurfaceArrayComponent << "\n";
  os << indent << "Splatting: " << this->Splatting << " (threshold " << this->SplatPixelThreshold
     << " pixels^2)\n";
  os << indent << "ProjectionColorMethod: " << this->ProjectionColorMethod << "\n";
  os << indent << "ProjectionOrder: " << this->ProjectionOrder << "\n";
  os << indent << "ProjectionOpacityLookup: " << this->ProjectionOpacityLookup << "\n";
  os << indent << "BlendMode: " << this->BlendMode << "\n";
  // Diagnostics of the last render.
  os << indent << "LastImageTime: " << this->LastImageTime << " s\n";
  os << indent << "LastRenderAborted: " << this->LastRenderAborted << "\n";
  os << indent << "LastRenderWasInteractive: " << this->LastRenderWasInteractive << "\n";
  os << indent << "LastSubsampling: " << this->LastSubsampling << "\n";
  os << indent << "LastDrawingMode: " << this->LastDrawingMode << "\n";
  os << indent << "WitnessViolations: " << this->WitnessViolations << "\n";
  os << indent << "NumberOfRenderedCells: " << this->NumberOfRenderedCells << "\n";
  os << indent << "NumberOfSkippedCells: " << this->NumberOfSkippedCells << "\n";
  os << indent << "NumberOfSegments: " << this->NumberOfSegments << "\n";
  os << indent << "NumberOfPieces: " << this->NumberOfPieces << "\n";
  os << indent << "NumberOfCellRecords: " << this->NumberOfCellRecords << "\n";
  os << indent << "NumberOfTransparentCells: " << this->NumberOfTransparentCells << "\n";
  os << indent << "NumberOfRays: " << this->NumberOfRays << "\n";
  os << indent << "NumberOfSplattedCells: " << this->NumberOfSplattedCells << "\n";
  os << indent << "NumberOfProjectedTriangles: " << this->NumberOfProjectedTriangles << "\n";
  os << indent << "NumberOfProjectedSlabs: " << this->NumberOfProjectedSlabs << "\n";
  os << indent << "ShadingErrorEstimate: " << this->ShadingErrorEstimate << "\n";
  hov::PrintFrameState(os, indent, this->Impl->LastShading, this->Impl->Audit.GetLast(),
    this->Impl->Scene.GetTransferFunction());
}
