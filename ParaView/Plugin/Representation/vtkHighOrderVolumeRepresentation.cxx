#include "vtkHighOrderVolumeRepresentation.h"

#include "hovParaViewNativePiece.h"     // the grid handed to the view
#include "hovParaViewStartup.h"         // threaded SMP backend, version check
#include "vtkPVHighOrderVolumeMapper.h" // the mapper

#include "vtkAlgorithmOutput.h"          // piece producers
#include "vtkColorTransferFunction.h"    // the colour map's vector mode
#include "vtkCellData.h"                 // the separate opacity array
#include "vtkCompositeDataSet.h"         // block selection
#include "vtkDataArray.h"                // its components
#include "vtkDiscretizableColorTransferFunction.h" // ParaView's colour maps
#include "vtkHighOrderTransferFunction.h" // colour sampling tolerance
#include "vtkInformation.h"              // pipeline and view requests
#include "vtkInformationVector.h"        // pipeline requests
#include "vtkMath.h"                     // UninitializeBounds
#include "vtkMatrix4x4.h"                // geometry bounds
#include "vtkMultiProcessController.h"   // rank in messages
#include "vtkObjectFactory.h"            // vtkStandardNewMacro
#include "vtkPVGeometryFilter.h"         // LOD geometry
#include "vtkPVLODVolume.h"              // the actor
#include "vtkPVRenderView.h"             // piece delivery, ordered compositing
#include "vtkPartitionedDataSet.h"       // no block selection for partitions
#include "vtkPointData.h"                // the separate opacity array
#include "vtkPolyDataMapper.h"           // LOD mapper
#include "vtkUnsignedCharArray.h"        // distinct cell types
#include "vtkUnstructuredGrid.h"         // the native piece
#include "vtkVolumeProperty.h"           // independent components

#include <algorithm> // std::max
#include <cstring>   // std::strcmp
#include <string>    // std::to_string

vtkStandardNewMacro(vtkHighOrderVolumeRepresentation);

vtkHighOrderVolumeRepresentation::vtkHighOrderVolumeRepresentation()
  : NativePiece(vtkSmartPointer<vtkUnstructuredGrid>::New())
{
  hov::ParaViewStartup();
  // Projected tetrahedra stay the superclass's default; ours is used instead
  // in UpdateMapperParameters.
  this->Actor->SetMapper(this->Mapper);
  this->SetColorSamplingTolerance(1e-4);
}

void vtkHighOrderVolumeRepresentation::SetColor(vtkColorTransferFunction* lut)
{
  this->ColorMap = lut;
  this->UpdateColorFunction();
}

void vtkHighOrderVolumeRepresentation::SetColorSamplingTolerance(double tolerance)
{
  this->ColorSamplingTolerance = tolerance;
  this->ApplyColorSamplingTolerance();
}

void vtkHighOrderVolumeRepresentation::ApplyColorSamplingTolerance()
{
  // The OpenGL projection is accurate to about 1/255 (M3 within 0.7/255 of
  // the CPU image); every colour node cuts every cell into one more slab, so
  // it linearises to 1e-3 (0.26/255) at the finest: ParaView's default colour
  // map then draws 2.7x faster (bracket, 300^2).
  const bool projection =
    this->Mapper->GetRenderMode() == vtkHighOrderVolumeMapper::OPENGL_PROJECTION;
  this->Mapper->GetTransferFunction()->SetSamplingTolerance(
    projection ? std::max(this->ColorSamplingTolerance, 1e-3) : this->ColorSamplingTolerance);
}

void vtkHighOrderVolumeRepresentation::UpdateColorFunction()
{
  auto* discretizable = vtkDiscretizableColorTransferFunction::SafeDownCast(this->ColorMap);
  if (!discretizable || !discretizable->GetDiscretize())
  {
    this->Property->SetColor(this->ColorMap);
    return;
  }
  // The same function without its 256-step table (the copy is a plain
  // vtkColorTransferFunction: nodes, colour space, clamping, range colours).
  if (this->ContinuousColorMapSource != discretizable ||
    this->ContinuousColorMapTime < discretizable->GetMTime())
  {
    this->ContinuousColorMap->DeepCopy(discretizable);
    this->ContinuousColorMapSource = discretizable;
    this->ContinuousColorMapTime = discretizable->GetMTime();
  }
  this->Property->SetColor(this->ContinuousColorMap);
}

vtkHighOrderVolumeRepresentation::~vtkHighOrderVolumeRepresentation() = default;

void vtkHighOrderVolumeRepresentation::SetActiveAssembly(const char* name)
{
  this->Assembly = name ? name : "";
  this->Superclass::SetActiveAssembly(name);
}

void vtkHighOrderVolumeRepresentation::AddBlockSelector(const char* selector)
{
  if (selector)
  {
    this->BlockSelectors.emplace_back(selector);
  }
  this->Superclass::AddBlockSelector(selector);
}

void vtkHighOrderVolumeRepresentation::RemoveAllBlockSelectors()
{
  this->BlockSelectors.clear();
  this->Superclass::RemoveAllBlockSelectors();
}

vtkPVHighOrderVolumeMapper* vtkHighOrderVolumeRepresentation::GetHighOrderMapper()
{
  return this->Mapper;
}

int vtkHighOrderVolumeRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkMath::UninitializeBounds(this->DataBounds);
  vtkDataObject* input = inputVector[0]->GetNumberOfInformationObjects() == 1
    ? vtkDataObject::GetData(inputVector[0], 0)
    : nullptr;
  // Not the superclass's Preprocessor: it would tetrahedralise.
  bool selectedNothing = false;
  this->NativePiece =
    hov::NativePiece(input, this->BlockSelectors, this->Assembly, selectedNothing);
  // Said once per selection: no selector at all (rank 0), or selectors whose
  // blocks hold no cells (one rank only: on several, the selected blocks may
  // all be on other ranks).
  std::string selection = this->Assembly;
  for (const std::string& selector : this->BlockSelectors)
  {
    selection += "\n" + selector;
  }
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  const int rank = controller ? controller->GetLocalProcessId() : 0;
  const bool noSelector = this->BlockSelectors.empty() &&
    vtkCompositeDataSet::SafeDownCast(input) && !vtkPartitionedDataSet::SafeDownCast(input);
  const bool warn = (noSelector && rank == 0) || (selectedNothing && ranks <= 1);
  if (warn && selection != this->WarnedSelection)
  {
    vtkWarningMacro("Accurate Volume: "
      << (noSelector ? std::string("no block is selected (\"Blocks\")")
                     : "the selected blocks (" + std::to_string(this->BlockSelectors.size()) +
                         " selectors) hold no unstructured cells")
      << "; nothing is drawn.");
  }
  this->WarnedSelection = warn ? selection : std::string("\n(none)");
  if (this->NativePiece->GetNumberOfCells() > 0)
  {
    this->NativePiece->GetBounds(this->DataBounds);
  }
  // vtkPVDataRepresentation's RequestData (cache and time handling).
  return this->vtkVolumeRepresentation::RequestData(request, inputVector, outputVector);
}

int vtkHighOrderVolumeRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  // vtkPVDataRepresentation's handling (visibility, caching); the
  // superclass's would hand the view its tetrahedralised grid.
  if (!this->vtkVolumeRepresentation::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }
  if (request_type == vtkPVView::REQUEST_UPDATE())
  {
    outInfo->Set(vtkPVRenderView::NEED_ORDERED_COMPOSITING(), 1);
    vtkPVRenderView::SetPiece(inInfo, this, this->NativePiece);
    vtkPVRenderView::SetOrderedCompositingConfiguration(inInfo, this,
      this->UseDataPartitions ? vtkPVRenderView::USE_BOUNDS_FOR_REDISTRIBUTION
                              : (vtkPVRenderView::DATA_IS_REDISTRIBUTABLE |
                                  vtkPVRenderView::USE_DATA_FOR_LOAD_BALANCING));
    // Each cell on exactly one rank: no cell is composited twice.
    vtkPVRenderView::SetRedistributionModeToUniquelyAssignBoundaryCells(inInfo, this);
    vtkPVRenderView::SetRequiresDistributedRendering(inInfo, this, true);
    vtkNew<vtkMatrix4x4> matrix;
    this->Actor->GetMatrix(matrix);
    vtkPVRenderView::SetGeometryBounds(inInfo, this, this->DataBounds, matrix);
    this->Actor->SetMapper(nullptr);
  }
  else if (request_type == vtkPVView::REQUEST_UPDATE_LOD())
  {
    this->LODGeometryFilter->SetInputData(vtkPVView::GetPiece(inInfo, this));
    this->LODGeometryFilter->SetUseOutline(
      inInfo->Has(vtkPVRenderView::USE_OUTLINE_FOR_LOD()) ? 1 : 0);
    this->LODGeometryFilter->Update();
    vtkPVRenderView::SetPieceLOD(inInfo, this, this->LODGeometryFilter->GetOutputDataObject(0));
  }
  else if (request_type == vtkPVView::REQUEST_RENDER())
  {
    vtkAlgorithmOutput* producerPort = vtkPVRenderView::GetPieceProducer(inInfo, this);
    vtkAlgorithmOutput* producerPortLOD = vtkPVRenderView::GetPieceProducerLOD(inInfo, this);
    auto* piece = producerPort
      ? vtkUnstructuredGridBase::SafeDownCast(producerPort->GetProducer()->GetOutputDataObject(0))
      : nullptr;
    this->RenderedPiece = piece; // the piece delivered for this frame (read by the next call)
    this->UpdateMapperParameters();
    this->RenderedPiece = nullptr;
    this->Actor->SetEnableLOD(inInfo->Has(vtkPVRenderView::USE_LOD()) ? 1 : 0);
    if (piece)
    {
      this->Mapper->SetInputConnection(producerPort);
      this->ReportPiece(piece);
    }
    else
    {
      this->Actor->SetMapper(nullptr);
    }
    this->LODMapper->SetInputConnection(producerPortLOD);
  }
  return 1;
}

void vtkHighOrderVolumeRepresentation::ReportPiece(vtkDataSet* piece)
{
  // ParaView draws no volume for an empty piece or without a colouring
  // array, so the mapper never sees either: say so here, once per piece.
  if (piece->GetMTime() <= this->ReportedPieceTime && this->GetInputArrayInformation(0) &&
    this->ReportedArray == this->CurrentArrayName())
  {
    return;
  }
  this->ReportedPieceTime = piece->GetMTime();
  this->ReportedArray = this->CurrentArrayName();
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int rank = controller ? controller->GetLocalProcessId() : 0;
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  if (piece->GetNumberOfCells() == 0 && ranks > 1)
  {
    vtkWarningMacro("Accurate Volume: rank " << rank << " of " << ranks
                                             << " received an empty piece (0 cells); it draws "
                                                "nothing, the other ranks draw the rest.");
  }
  else if (this->ReportedArray.empty() && piece->GetNumberOfCells() > 0 && rank == 0)
  {
    vtkWarningMacro("Accurate Volume needs a point or cell array to colour by (\"Solid Color\" "
                    "draws no volume): choose one in the Coloring menu or with ColorBy().");
  }
}

std::string vtkHighOrderVolumeRepresentation::CurrentArrayName()
{
  vtkInformation* info = this->GetInputArrayInformation(0);
  const char* name = info && info->Has(vtkDataObject::FIELD_NAME())
    ? info->Get(vtkDataObject::FIELD_NAME())
    : nullptr;
  return name ? name : "";
}

void vtkHighOrderVolumeRepresentation::UpdateMapperParameters()
{
  const char* colorArrayName = nullptr;
  int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  vtkInformation* info = this->GetInputArrayInformation(0);
  if (info && info->Has(vtkDataObject::FIELD_ASSOCIATION()) &&
    info->Has(vtkDataObject::FIELD_NAME()))
  {
    colorArrayName = info->Get(vtkDataObject::FIELD_NAME());
    association = info->Get(vtkDataObject::FIELD_ASSOCIATION());
  }
  const int colorAssociation = association;
  this->UpdateColorFunction(); // the colour map may have changed since SetColor
  vtkColorTransferFunction* ctf = this->ColorMap;
  const bool component = ctf && ctf->GetVectorMode() == vtkScalarsToColors::COMPONENT;
  int extinctionComponent = component ? ctf->GetVectorComponent() : -1;
  const char* extinctionArray = colorArrayName;
  std::string colorField = this->SeparateColorArray;
  int colorComponent = this->SeparateColorArrayComponent;
  if (this->UseSeparateOpacityArray && !this->OpacityArrayName.empty())
  {
    // ParaView's separate opacity array: extinction from it, colour from the colouring array.
    extinctionArray = this->OpacityArrayName.c_str();
    association = this->OpacityArrayFieldAssociation;
    extinctionComponent = this->OpacityArrayComponent;
    // ParaView's OpacityComponent counts the magnitude as the component after
    // the last: the mapper's MAGNITUDE (component 0 of a one-component array).
    // The piece this rank renders (delivered after ParaView's redistribution),
    // else its own.
    vtkDataSet* piece = this->RenderedPiece ? this->RenderedPiece
                                            : static_cast<vtkDataSet*>(this->NativePiece);
    vtkDataSetAttributes* fields = association == vtkDataObject::FIELD_ASSOCIATION_CELLS
      ? static_cast<vtkDataSetAttributes*>(piece->GetCellData())
      : static_cast<vtkDataSetAttributes*>(piece->GetPointData());
    vtkDataArray* opacity = fields->GetArray(extinctionArray);
    const int components = opacity ? opacity->GetNumberOfComponents() : 0;
    if (components > 0 && extinctionComponent >= components)
    {
      extinctionComponent = components > 1 ? -1 : 0;
    }
    if (colorAssociation == vtkDataObject::FIELD_ASSOCIATION_CELLS)
    {
      // The mapper's separate colour field is a point field.
      if (!this->WarnedCellColorArray)
      {
        this->WarnedCellColorArray = true;
        vtkWarningMacro("Use Separate Opacity Array: the colouring array '"
          << (colorArrayName ? colorArrayName : "") << "' is a cell array; Accurate Volume "
          << "takes a separate colour from a point array only, so the colour comes from "
          << (colorField.empty() ? "the colour map applied to the opacity array '" +
                  std::string(extinctionArray) + "'"
                                 : "the separate colour array '" + colorField + "'")
          << ".");
      }
    }
    else
    {
      this->WarnedCellColorArray = false;
      colorField = colorArrayName ? colorArrayName : "";
      colorComponent = component ? ctf->GetVectorComponent() : -1;
    }
  }
  this->Mapper->SelectScalarArray(extinctionArray);
  this->Mapper->SetScalarMode(association == vtkDataObject::FIELD_ASSOCIATION_CELLS
      ? VTK_SCALAR_MODE_USE_CELL_FIELD_DATA
      : VTK_SCALAR_MODE_USE_POINT_FIELD_DATA);
  this->Mapper->SetVectorMode(extinctionComponent >= 0 ? vtkHighOrderVolumeMapper::COMPONENT
                                                       : vtkHighOrderVolumeMapper::MAGNITUDE);
  this->Mapper->SetVectorComponent(std::max(extinctionComponent, 0));
  this->Mapper->SetColorArrayName(colorField.empty() ? nullptr : colorField.c_str());
  this->Mapper->SetColorArrayComponent(colorComponent);
  this->UpdateLODMapper(colorArrayName, colorAssociation);
  // ParaView sets the functions of component 0 only: the mapper uses those.
  this->Property->SetIndependentComponents(false);
  // Each said once.
  if (!this->MapScalars && !this->WarnedMapScalars)
  {
    this->WarnedMapScalars = true;
    vtkWarningMacro("Accurate Volume always maps one scalar through the colour map and opacity "
                    "function; 'Map Scalars' off is ignored.");
  }
  if (this->MultiComponentsMapping && !this->WarnedMultiComponents)
  {
    this->WarnedMultiComponents = true;
    vtkWarningMacro("Accurate Volume always maps one scalar through the colour map and opacity "
                    "function; 'Multi Components Mapping' is ignored.");
  }
  this->Actor->SetMapper(this->Mapper);
}

void vtkHighOrderVolumeRepresentation::UpdateLODMapper(const char* arrayName, int association)
{
  // The surface drawn while interacting above the view's LOD threshold:
  // coloured by the colouring array through ParaView's colour map (its
  // range and vector mode), as ParaView's surfaces are.
  const bool colored = arrayName && arrayName[0] && this->ColorMap;
  this->LODMapper->SetScalarVisibility(colored ? 1 : 0);
  this->LODMapper->SelectColorArray(colored ? arrayName : nullptr);
  this->LODMapper->SetScalarMode(association == vtkDataObject::FIELD_ASSOCIATION_CELLS
      ? VTK_SCALAR_MODE_USE_CELL_FIELD_DATA
      : VTK_SCALAR_MODE_USE_POINT_FIELD_DATA);
  this->LODMapper->SetLookupTable(this->ColorMap);
  this->LODMapper->SetUseLookupTableScalarRange(1);
  this->LODMapper->SetColorModeToMapScalars(); // also 8-bit arrays, as ParaView's surfaces
  this->LODMapper->SetInterpolateScalarsBeforeMapping(1);
}

// ---- forwarded settings ------------------------------------------------------
void vtkHighOrderVolumeRepresentation::SetRenderMode(int mode)
{
  this->Mapper->SetRenderMode(mode);
  this->ApplyColorSamplingTolerance();
}
void vtkHighOrderVolumeRepresentation::SetBlendMode(int mode)
{
  this->Mapper->SetBlendMode(mode);
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  if (ranks > 1 && mode != vtkHighOrderVolumeMapper::COMPOSITE_BLEND &&
    controller->GetLocalProcessId() == 0)
  {
    // ParaView composites the ranks' images with "over" in depth order, which
    // is not the maximum, minimum or average along the whole ray.
    vtkWarningMacro("Accurate Volume: with " << ranks << " ranks a blend mode other than "
                                             << "Composite is exact within each rank's piece "
                                             << "only; ParaView composites the pieces' images "
                                             << "with 'over'. Use one rank for an exact image.");
  }
}
void vtkHighOrderVolumeRepresentation::SetOpacitySemantics(int semantics)
{
  this->Mapper->SetOpacitySemantics(semantics);
}
void vtkHighOrderVolumeRepresentation::SetGPUOpacityTolerance(double tolerance)
{
  this->Mapper->SetGPUOpacityTolerance(tolerance);
}
void vtkHighOrderVolumeRepresentation::SetEmissionModel(int model)
{
  this->Mapper->SetEmissionModel(model);
}
void vtkHighOrderVolumeRepresentation::SetEmissionScale(double scale)
{
  this->Mapper->SetEmissionScale(scale);
}
void vtkHighOrderVolumeRepresentation::SetIntegrationMethod(int method)
{
  this->Mapper->SetIntegrationMethod(method);
}
void vtkHighOrderVolumeRepresentation::SetCellOrdering(int ordering)
{
  this->Mapper->SetCellOrdering(ordering);
}
void vtkHighOrderVolumeRepresentation::SetTerminationTransmittance(double value)
{
  this->Mapper->SetTerminationTransmittance(value);
}
void vtkHighOrderVolumeRepresentation::SetRayCastTolerance(double tolerance)
{
  this->Mapper->SetRayCastTolerance(tolerance);
}
void vtkHighOrderVolumeRepresentation::SetProjectionColorMethod(int method)
{
  this->Mapper->SetProjectionColorMethod(method);
}
void vtkHighOrderVolumeRepresentation::SetProjectionOrder(int order)
{
  this->Mapper->SetProjectionOrder(order);
}
void vtkHighOrderVolumeRepresentation::SetUseDepthBuffer(int use)
{
  this->Mapper->SetUseDepthBuffer(use != 0);
}
void vtkHighOrderVolumeRepresentation::SetSkipTransparentCells(int skip)
{
  this->Mapper->SetSkipTransparentCells(skip != 0);
}
void vtkHighOrderVolumeRepresentation::AddIsosurface(
  double value, double r, double g, double b, double opacity)
{
  this->Mapper->AddIsosurface(value, r, g, b, opacity);
}
void vtkHighOrderVolumeRepresentation::RemoveAllIsosurfaces()
{
  this->Mapper->RemoveAllIsosurfaces();
}

namespace
{
/// "None" (the array list's none string) and empty names mean: no separate array.
bool IsNone(const char* name)
{
  return !name || !*name || std::strcmp(name, "None") == 0;
}
}

void vtkHighOrderVolumeRepresentation::SetSeparateColorArray(const char* name)
{
  this->SeparateColorArray = IsNone(name) ? "" : name;
}
void vtkHighOrderVolumeRepresentation::SetSeparateColorArrayComponent(int component)
{
  this->SeparateColorArrayComponent = component;
}
void vtkHighOrderVolumeRepresentation::SetIsosurfaceArray(const char* name)
{
  this->Mapper->SetIsosurfaceArrayName(IsNone(name) ? nullptr : name);
}
void vtkHighOrderVolumeRepresentation::SetIsosurfaceArrayComponent(int component)
{
  this->Mapper->SetIsosurfaceArrayComponent(component);
}
void vtkHighOrderVolumeRepresentation::SetFloatImageFileName(const char* name)
{
  this->Mapper->SetFloatImageFileName(name ? name : "");
}

// ---- diagnostics ---------------------------------------------------------------
vtkIdType vtkHighOrderVolumeRepresentation::GetWitnessViolations()
{
  return this->Mapper->GetWitnessViolations();
}
vtkIdType vtkHighOrderVolumeRepresentation::GetNumberOfRenderedCells()
{
  return this->Mapper->GetNumberOfRenderedCells();
}
vtkIdType vtkHighOrderVolumeRepresentation::GetNumberOfSkippedCells()
{
  return this->Mapper->GetNumberOfSkippedCells();
}
vtkIdType vtkHighOrderVolumeRepresentation::GetNumberOfTransparentCells()
{
  return this->Mapper->GetNumberOfTransparentCells();
}
double vtkHighOrderVolumeRepresentation::GetLastImageTime()
{
  return this->Mapper->GetLastImageTime();
}
double vtkHighOrderVolumeRepresentation::GetLastFrameTime()
{
  return this->Mapper->GetLastFrameTime();
}
double vtkHighOrderVolumeRepresentation::GetRayCastErrorEstimate()
{
  return this->Mapper->GetRayCastErrorEstimate();
}
vtkIdType vtkHighOrderVolumeRepresentation::GetNumberOfRenderCalls()
{
  return this->Mapper->GetNumberOfRenderCalls();
}
int vtkHighOrderVolumeRepresentation::GetLastRayCastSubsampling()
{
  return this->Mapper->GetLastRayCastSubsampling();
}
vtkIdType vtkHighOrderVolumeRepresentation::GetNumberOfPieceCells()
{
  vtkUnstructuredGridBase* piece = this->Mapper->GetInput();
  return piece ? piece->GetNumberOfCells() : 0;
}
int vtkHighOrderVolumeRepresentation::GetNumberOfPieceCellTypes()
{
  auto* piece = vtkUnstructuredGrid::SafeDownCast(this->Mapper->GetInput());
  vtkUnsignedCharArray* types = piece ? piece->GetDistinctCellTypesArray() : nullptr;
  return types ? static_cast<int>(types->GetNumberOfTuples()) : 0;
}

void vtkHighOrderVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SeparateColorArray: " << this->SeparateColorArray << " component "
     << this->SeparateColorArrayComponent << "\n";
  os << indent << "Mapper:\n";
  this->Mapper->PrintSelf(os, indent.GetNextIndent());
}
