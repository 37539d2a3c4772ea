#include "vtkHighOrderVolumeMapper.h"

#include "hovCellProjector.h" // CPU path
#include "hovFeatureSetup.h"  // isosurfaces, fields, splatting
#include "hovImageDisplay.h"  // OpenGL blit of the float image
#include "hovProjectionBackend.h"    // OPENGL_PROJECTION mode
#include "hovRayCastBackend.h"  // RAY_CAST mode
#include "hovCellSetup.h"    // per-cell preparation
#include "vtkHighOrderTransferFunction.h"
#include "hovViewRays.h" // pixel rays

#include "hovTransferFunction.h" // the kernel table

#include "vtkSteinVisibilitySort.h" // the default (exact) visibility sort

#include "vtkCamera.h"
#include "vtkCommand.h" // ProgressEvent
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h" // CheckAbortStatus
#include "vtkRenderer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGridBase.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm> // std::reverse
#include <string>    // setup errors
#include <vector>    // buffers

vtkStandardNewMacro(vtkHighOrderVolumeMapper);


vtkCxxSetObjectMacro(vtkHighOrderVolumeMapper, VisibilitySort, vtkVisibilitySort);

struct vtkHighOrderVolumeMapper::Internals
{
  hov::CellSetup Setup;
  vtkMTimeType SetupInputTime = 0;
  vtkDataArray* SetupArray = nullptr;
  vtkMTimeType SetupArrayTime = 0;
  int SetupComponent = -2;
  bool SetupCellScalars = false;
  bool SetupValid = false;
  unsigned long SetupGeneration = 0;

  std::vector<vtkIdType> FrontToBack;
  vtkCamera* OrderCamera = nullptr;
  vtkMTimeType OrderCameraTime = 0;
  vtkMTimeType OrderMatrixTime = 0;
  vtkMTimeType OrderSortTime = 0;
  unsigned long OrderGeneration = ~0ul;
  // The Stein sort found a cycle in the current order: composite per pixel.
  bool OrderHasCycles = false;
  unsigned long CycleWarningGeneration = ~0ul;

  vtkNew<vtkHighOrderTransferFunction> TransferFunction;
  hov::CellProjector Projector;
  hov::ImageDisplay Display;
  vtkNew<vtkImageData> FloatImage;
  std::vector<double> RGBA;
  std::vector<float> Depth;
};

vtkHighOrderVolumeMapper::vtkHighOrderVolumeMapper()
  : ProjectionImpl(new hov::ProjectionState)
  , RayCastImpl(new hov::RayCastState)
  , Impl(new Internals)
  , FeatureImpl(new hov::FeatureSetup)
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

vtkHighOrderTransferFunction* vtkHighOrderVolumeMapper::GetTransferFunction()
{
  return this->Impl->TransferFunction;
}

bool vtkHighOrderVolumeMapper::PrepareCells(vtkVolume*)
{
  Internals& impl = *this->Impl;
  vtkUnstructuredGridBase* input = this->GetInput();
  int cellFlag = 0;
  vtkDataArray* scalars = vtkAbstractMapper::GetScalars(input, this->ScalarMode,
    this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
  if (!scalars)
  {
    vtkErrorMacro("No numeric scalars to render: set point scalars on the input or select a "
                  "numeric point/cell array with SelectScalarArray().");
    impl.SetupValid = false;
    return false;
  }
  const bool cellScalars = cellFlag == 1;
  const int nc = scalars->GetNumberOfComponents();
  int component = -1;
  if (nc > 1 && this->VectorMode == COMPONENT)
  {
    component = std::min(std::max(this->VectorComponent, 0), nc - 1);
    if (component != this->VectorComponent)
    {
      vtkWarningMacro("VectorComponent " << this->VectorComponent << " out of range for array '"
                                         << (scalars->GetName() ? scalars->GetName() : "")
                                         << "' with " << nc << " components; using " << component);
    }
  }
  if (nc == 1)
  {
    component = 0;
  }
  if (impl.SetupValid && impl.SetupInputTime == input->GetMTime() && impl.SetupArray == scalars &&
    impl.SetupArrayTime == scalars->GetMTime() && impl.SetupComponent == component &&
    impl.SetupCellScalars == cellScalars)
  {
    return true;
  }
  impl.SetupInputTime = input->GetMTime();
  impl.SetupArray = scalars;
  impl.SetupArrayTime = scalars->GetMTime();
  impl.SetupComponent = component;
  impl.SetupCellScalars = cellScalars;
  impl.SetupValid = true;
  ++impl.SetupGeneration;
  std::string error;
  if (!impl.Setup.Build(input, scalars, cellScalars, component, &error) && !error.empty())
  {
    vtkErrorMacro("Cannot render: " << error << ".");
    impl.SetupValid = false;
    return false;
  }
  const hov::CellSetup::Statistics& st = impl.Setup.GetStatistics();
  if (st.Cells == 0)
  {
    vtkWarningMacro("The input grid has no cells: nothing to render.");
  }
  if (st.Unsupported)
  {
    vtkWarningMacro(<< st.Unsupported << " of " << st.Cells << " cells are of types not yet "
                    << "supported by the CPU projection path (first type: "
                    << st.FirstUnsupportedType << "; supported: 10-14, 24-27, 29); they are "
                    << "skipped.");
  }
  if (st.NonFinitePoints || st.NonFiniteScalars || st.Degenerate)
  {
    vtkWarningMacro(<< "Skipped cells: " << st.NonFinitePoints << " with NaN/Inf points or bad "
                    << "connectivity, " << st.NonFiniteScalars << " with NaN/Inf scalars, "
                    << st.Degenerate << " degenerate (zero-volume or tangled) cells.");
  }
  if (st.Inverted)
  {
    vtkWarningMacro(<< st.Inverted << " tetrahedra are inverted (negative orientation); they are "
                    << "rendered as the convex hull of their vertices.");
  }
  if (st.InvertedGeneral)
  {
    vtkWarningMacro(<< st.InvertedGeneral << " non-tetrahedral cells are inverted (mirrored node "
                    << "order); they are rendered as the region their corners bound.");
  }
  if (st.Curved)
  {
    vtkWarningMacro(<< st.Curved << " quadratic cells have curved geometry (max node deviation "
                    << st.MaxCurvature << " of the cell size); they are rendered with straight "
                    << "edges and their quadratic field (curved geometry needs the ray caster).");
  }
  return true;
}

bool vtkHighOrderVolumeMapper::PrepareOrder(
  vtkCamera* camera, vtkVolume* volume, bool needVisibilitySort)
{
  Internals& impl = *this->Impl;
  if (this->CellOrdering == PER_PIXEL_SORT && !needVisibilitySort)
  {
    // Any order will do: each pixel sorts its own segments.
    const vtkIdType n = impl.Setup.GetNumberOfRenderedCells();
    if (impl.OrderGeneration != impl.SetupGeneration || impl.OrderCamera != nullptr ||
      static_cast<vtkIdType>(impl.FrontToBack.size()) != n)
    {
      impl.FrontToBack.resize(n);
      for (vtkIdType i = 0; i < n; ++i)
      {
        impl.FrontToBack[i] = i;
      }
      impl.OrderGeneration = impl.SetupGeneration;
      impl.OrderCamera = nullptr;
    }
    impl.OrderHasCycles = false;
    return true;
  }
  vtkMatrix4x4* matrix = volume->GetMatrix();
  if (!this->VisibilitySort)
  {
    vtkErrorMacro("No visibility sort set.");
    return false;
  }
  if (impl.OrderGeneration == impl.SetupGeneration && impl.OrderCamera == camera &&
    impl.OrderCameraTime == camera->GetMTime() && impl.OrderMatrixTime == matrix->GetMTime() &&
    impl.OrderSortTime == this->VisibilitySort->GetMTime())
  {
    return true; // same view: reuse the order (also keeps ties deterministic)
  }
  // The sort sees only the valid cells (never a cell with broken
  // connectivity or NaN points), and its ids are rendered-cell indices.
  vtkVisibilitySort* sort = this->VisibilitySort;
  sort->SetInput(impl.Setup.GetSortGrid());
  sort->SetCamera(camera);
  sort->SetModelTransform(matrix);
  sort->SetDirectionToBackToFront();
  sort->InitTraversal();
  impl.FrontToBack.clear();
  const vtkIdType numRendered = impl.Setup.GetNumberOfRenderedCells();
  impl.FrontToBack.reserve(numRendered);
  while (vtkIdTypeArray* cells = sort->GetNextCells())
  {
    const vtkIdType n = cells->GetNumberOfTuples();
    for (vtkIdType i = 0; i < n; ++i)
    {
      const vtkIdType cell = cells->GetValue(i);
      if (cell >= 0 && cell < numRendered)
      {
        impl.FrontToBack.push_back(cell);
      }
    }
  }
  std::reverse(impl.FrontToBack.begin(), impl.FrontToBack.end());
  vtkSteinVisibilitySort* stein = vtkSteinVisibilitySort::SafeDownCast(sort);
  impl.OrderHasCycles = stein && stein->GetNumberOfCycles() > 0;
  if (impl.OrderHasCycles && impl.CycleWarningGeneration != impl.SetupGeneration)
  {
    impl.CycleWarningGeneration = impl.SetupGeneration; // once per input
    vtkWarningMacro("The visibility order of this view has " << stein->GetNumberOfCycles()
                                                          << " cycle(s); frames with cycles are "
                                                             "composited with PER_PIXEL_SORT.");
  }
  if (static_cast<vtkIdType>(impl.FrontToBack.size()) != numRendered)
  {
    vtkWarningMacro("The visibility sort returned " << impl.FrontToBack.size() << " of "
                                                    << numRendered << " cells.");
  }
  impl.OrderGeneration = impl.SetupGeneration;
  impl.OrderCamera = camera;
  impl.OrderCameraTime = camera->GetMTime();
  impl.OrderMatrixTime = matrix->GetMTime();
  impl.OrderSortTime = this->VisibilitySort->GetMTime();
  return true;
}

bool vtkHighOrderVolumeMapper::ValidateInputs(
  vtkCamera* camera, vtkVolume* volume, int width, int height, double aspect)
{
  if (!camera || !volume || width <= 0 || height <= 0)
  {
    vtkErrorMacro("RenderImage needs a camera, a volume and a positive size.");
    return false;
  }
  if (!this->CheckFrameView(camera, volume, aspect))
  {
    return false; // the error was reported
  }
  if (this->GetNumberOfInputConnections(0) > 0)
  {
    this->GetInputAlgorithm()->Update(); // RenderImage may run before any render
  }
  if (!this->GetInput())
  {
    vtkErrorMacro("No input.");
    return false;
  }
  if (!volume->GetProperty())
  {
    vtkErrorMacro("The volume has no vtkVolumeProperty.");
    return false;
  }
  if (!this->PrepareCells(volume))
  {
    return false; // the error was reported
  }
  const hov::CellSetup::Statistics& st = this->Impl->Setup.GetStatistics();
  this->NumberOfRenderedCells = st.Rendered;
  this->NumberOfSkippedCells = st.Cells - st.Rendered;
  return true;
}

bool vtkHighOrderVolumeMapper::PrepareTransferFunction(vtkVolumeProperty* property, bool* rebuilt)
{
  Internals& impl = *this->Impl;
  vtkHighOrderTransferFunction* tf = impl.TransferFunction;
  tf->SetOpacitySemantics(this->OpacitySemantics);
  tf->SetGPUTolerance(this->GPUOpacityTolerance);
  tf->SetEmissionScale(this->EmissionScale);
  // One component of a multi-component array with independent components
  // uses that component's functions; everything else uses component 0's.
  const bool independent = impl.SetupComponent > 0 && property->GetIndependentComponents();
  tf->SetComponent(independent ? std::min(impl.SetupComponent, 3) : 0);
  const int buildsBefore = tf->GetBuildCount();
  tf->Update(property);
  if (tf->GetBuildCount() != buildsBefore)
  {
    for (int i = 0; i < tf->GetNumberOfMessages(); ++i)
    {
      vtkWarningMacro("Transfer function: " << tf->GetMessage(i));
    }
  }
  if (rebuilt)
  {
    *rebuilt = tf->GetBuildCount() != buildsBefore;
  }
  // Nothing absorbs: nothing to see, unless the glow does not need extinction.
  return tf->GetTable().HasExtinction() || this->EmissionModel == WILHELMS_VAN_GELDER;
}

void vtkHighOrderVolumeMapper::PublishImage(int width, int height, bool drawn)
{
  Internals& impl = *this->Impl;
  this->CheckFrameImage(impl.RGBA.data(), impl.RGBA.size() / 4, drawn);
  vtkImageData* image = impl.FloatImage;
  image->SetDimensions(std::max(width, 0), std::max(height, 0), 1);
  vtkNew<vtkFloatArray> array;
  array->SetName("RGBA");
  array->SetNumberOfComponents(4);
  array->SetNumberOfTuples(static_cast<vtkIdType>(impl.RGBA.size() / 4));
  float* out = array->GetPointer(0);
  for (size_t i = 0; i < impl.RGBA.size(); ++i)
  {
    out[i] = static_cast<float>(impl.RGBA[i]);
  }
  image->GetPointData()->SetScalars(array);
}

int vtkHighOrderVolumeMapper::ComputeImage(
  vtkCamera* camera, vtkVolume* volume, int width, int height, double aspect, const float* depth)
{
  Internals& impl = *this->Impl;
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  this->LastRenderAborted = false;
  this->AbortExecute = 0; // a request to abort applies to one render
  this->UpdateProgress(0.0);
  if (this->RenderMode == RAY_CAST)
  {
    bool drawn = false;
    const int status =
      this->ComputeRayCastImage(camera, volume, width, height, aspect, depth, impl.RGBA, drawn);
    this->PublishImage(width, height, drawn);
    if (!this->LastRenderAborted && this->GetProgress() < 1.0)
    {
      this->UpdateProgress(1.0); // nothing to trace
    }
    timer->StopTimer();
    this->LastImageTime = timer->GetElapsedTime();
    return status;
  }
  this->WitnessViolations = this->NumberOfSegments = this->NumberOfPieces = 0;
  this->NumberOfRays = 0;
  this->NumberOfSplattedCells = 0;
  this->NumberOfRenderedCells = this->NumberOfSkippedCells = 0;

  bool ok = this->ValidateInputs(camera, volume, width, height, aspect);
  // Isosurfaces are visible even where the volume does not absorb.
  bool render = ok && impl.Setup.GetNumberOfRenderedCells() > 0;
  bool rebuilt = false;
  if (render && !this->PrepareTransferFunction(volume->GetProperty(), &rebuilt) &&
    this->GetNumberOfIsosurfaces() == 0)
  {
    if (rebuilt)
    {
      this->WarnTransparent();
    }
    render = false;
  }
  hov::ViewRays rays;
  if (render && !rays.Setup(camera, volume->GetMatrix(), width, height, aspect))
  {
    vtkErrorMacro("Singular camera or volume matrix: nothing rendered.");
    render = ok = false;
  }
  if (render)
  {
    rays.SetupClipping(this, camera, volume->GetMatrix(),
      this->ViewDepthClipping ? this->ViewDepthRange : nullptr);
  }
  render = render && this->PrepareOrder(camera, volume);
  if (!render)
  {
    impl.RGBA.assign(static_cast<size_t>(std::max(width, 0)) * std::max(height, 0) * 4, 0.0);
  }
  else
  {
    // The projector sizes the image and writes every pixel: no clearing.
    hov::CellProjector::Settings settings;
    settings.Integration.Emission = static_cast<hov::EmissionModel>(this->EmissionModel);
    settings.Integration.Method = static_cast<hov::SegmentMethod>(this->IntegrationMethod);
    settings.TerminationTransmittance = this->TerminationTransmittance;
    // A cyclic order cannot be exact: fall back to the per-pixel order.
    settings.PerPixelSort = this->CellOrdering == PER_PIXEL_SORT || impl.OrderHasCycles;
    settings.TileSize = this->TileSize;
    vtkRenderWindow* window = this->FrameRenderer ? this->FrameRenderer->GetRenderWindow() : nullptr;
    if (this->HasObserver(vtkCommand::ProgressEvent) ||
      (window && window->HasObserver(vtkCommand::AbortCheckEvent)))
    {
      settings.Progress = [this](double done) { return this->ReportTileProgress(done); };
    }
    const int features = this->PrepareFeatures(camera, volume);
    hov::CellProjector::Statistics st;
    if (features > 0) // isosurfaces, separate fields or splatting: the feature path
    {
      st = this->FeatureImpl->GetProjector().Render(impl.Setup, impl.FrontToBack, rays,
        impl.TransferFunction->GetTable(), settings, this->FeatureImpl->GetFeatures(), depth,
        impl.RGBA);
      this->NumberOfSplattedCells = this->FeatureImpl->GetProjector().GetNumberOfSplats();
    }
    else if (features == 0)
    {
      st = impl.Projector.Render(impl.Setup, impl.FrontToBack, rays,
        impl.TransferFunction->GetTable(), settings, depth, impl.RGBA);
    }
    else
    {
      impl.RGBA.assign(static_cast<size_t>(width) * height * 4, 0.0);
    }
    this->LastRenderAborted = st.Aborted;
    this->WitnessViolations = st.WitnessViolations;
    this->NumberOfSegments = st.Segments;
    this->NumberOfPieces = st.Pieces;
  }
  this->PublishImage(width, height, render);
  if (!this->LastRenderAborted && this->GetProgress() < 1.0)
  {
    this->UpdateProgress(1.0); // nothing to render, or no tile loop
  }
  timer->StopTimer();
  this->LastImageTime = timer->GetElapsedTime();
  return ok ? 1 : 0;
}

bool vtkHighOrderVolumeMapper::ReportTileProgress(double done)
{
  // Called on the rendering thread between tile batches (hovTileBatches.h).
  this->UpdateProgress(done);
  vtkRenderWindow* window = this->FrameRenderer ? this->FrameRenderer->GetRenderWindow() : nullptr;
  return this->AbortExecute || (window && window->CheckAbortStatus());
}

int vtkHighOrderVolumeMapper::RenderImage(vtkCamera* camera, vtkVolume* volume, int width, int height)
{
  return this->ComputeImage(
    camera, volume, width, height, height > 0 ? static_cast<double>(width) / height : 1.0, nullptr);
}

bool vtkHighOrderVolumeMapper::PrepareProjectionFrame(vtkCamera* camera, vtkVolume* volume,
  double aspect, bool exactOrder, const hov::CellSetup** setup, const std::vector<vtkIdType>** frontToBack,
  vtkHighOrderTransferFunction** tf)
{
  Internals& impl = *this->Impl;
  *setup = &impl.Setup;
  *frontToBack = &impl.FrontToBack;
  *tf = impl.TransferFunction;
  this->NumberOfRenderedCells = this->NumberOfSkippedCells = 0;
  if (!this->ValidateInputs(camera, volume, 1, 1, aspect) ||
    impl.Setup.GetNumberOfRenderedCells() == 0)
  {
    return false;
  }
  bool rebuilt = false;
  if (!this->PrepareTransferFunction(volume->GetProperty(), &rebuilt))
  {
    if (rebuilt)
    {
      this->WarnTransparent();
    }
    return false;
  }
  return !exactOrder || this->PrepareOrder(camera, volume, true);
}

void vtkHighOrderVolumeMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  if (this->RenderMode == OPENGL_PROJECTION)
  {
    this->RenderProjection(ren, vol);
    return;
  }
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  int width = 0, height = 0, x0 = 0, y0 = 0;
  ren->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  if (width <= 0 || height <= 0)
  {
    return;
  }
  Internals& impl = *this->Impl;
  const float* depth = nullptr;
  if (this->UseDepthBuffer)
  {
    impl.Depth.resize(static_cast<size_t>(width) * height);
    if (hov::ImageDisplay::ReadDepth(ren, width, height, x0, y0, impl.Depth.data()))
    {
      depth = impl.Depth.data();
    }
    else
    {
      vtkWarningMacro("Could not read the depth buffer; opaque geometry will not clip the volume.");
    }
  }
  // The same aspect VTK's own mappers and actors use for the projection.
  const double tiledAspect = ren->GetTiledAspectRatio();
  this->FrameRenderer = ren; // its lights shade the isosurfaces
  this->ComputeImage(ren->GetActiveCamera(), vol, width, height, tiledAspect, depth);
  this->FrameRenderer = nullptr;
  vtkDataArray* rgba = impl.FloatImage->GetPointData()->GetScalars();
  if (rgba && rgba->GetNumberOfTuples() == static_cast<vtkIdType>(width) * height)
  {
    if (!impl.Display.Draw(ren, static_cast<vtkFloatArray*>(rgba)->GetPointer(0), width, height))
    {
      vtkErrorMacro("Could not draw the volume image with OpenGL.");
    }
  }
  timer->StopTimer();
  this->TimeToDraw = timer->GetElapsedTime();
}

void vtkHighOrderVolumeMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Impl->Display.ReleaseGraphicsResources(win);
  this->ProjectionImpl->Renderer.ReleaseGraphicsResources(win);
  this->Superclass::ReleaseGraphicsResources(win);
}

void vtkHighOrderVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderMode: " << this->RenderMode << " (projection colour method "
     << this->ProjectionColorMethod << ", order " << this->ProjectionOrder << ", opacity lookup "
     << this->ProjectionOpacityLookup << ")\n";
  os << indent << "RayCastTolerance: " << this->RayCastTolerance << " (interactive above "
     << this->RayCastInteractiveUpdateRate << " frames/s)\n";
  os << indent << "RayCastInteractiveSubsampling: " << this->RayCastInteractiveSubsampling
     << " (0: from the time budget; last frame " << this->LastRayCastSubsampling << ")\n";
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
  os << indent << "WitnessViolations: " << this->WitnessViolations << "\n";
  os << indent << "NumberOfRenderedCells: " << this->NumberOfRenderedCells << "\n";
  os << indent << "NumberOfSkippedCells: " << this->NumberOfSkippedCells << "\n";
}
