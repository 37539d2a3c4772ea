#include "vtkPVHighOrderVolumeMapper.h"

#include "vtkDataArray.h"               // the error estimate
#include "vtkFloatArray.h"              // an empty piece's float image
#include "vtkImageData.h"               // the float image
#include "vtkMultiProcessController.h"  // the rank in file names
#include "vtkObjectFactory.h"           // vtkStandardNewMacro
#include "vtkPointData.h"               // the error estimate
#include "vtkRenderer.h"                // an empty piece's viewport
#include "vtkTimerLog.h"                // frame time
#include "vtkUnstructuredGridBase.h"    // the piece
#include "vtkXMLImageDataWriter.h"      // float image file

#include <algorithm> // std::max
#include <sstream>   // file names

vtkStandardNewMacro(vtkPVHighOrderVolumeMapper);

namespace
{
/// This process's rank and the number of ranks (0 and 1 without MPI).
void RankAndSize(int& rank, int& size)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  rank = controller ? controller->GetLocalProcessId() : 0;
  size = controller ? controller->GetNumberOfProcesses() : 1;
}
}

vtkPVHighOrderVolumeMapper::vtkPVHighOrderVolumeMapper() = default;

vtkPVHighOrderVolumeMapper::~vtkPVHighOrderVolumeMapper() = default;

void vtkPVHighOrderVolumeMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  ++this->NumberOfRenderCalls;
  vtkUnstructuredGridBase* input = this->GetInput();
  if (input && input->GetNumberOfCells() == 0)
  {
    // An empty piece (ParaView's redistribution may leave a rank without
    // cells; the representation says so once per piece): the layer stays
    // transparent and the other ranks composite over it as usual.
    this->PublishEmptyLayer(ren);
  }
  else
  {
    this->Superclass::Render(ren, vol);
  }
  timer->StopTimer();
  this->LastFrameTime = timer->GetElapsedTime();
  if (!this->FloatImageFileName.empty())
  {
    this->WriteFloatImage();
  }
}

void vtkPVHighOrderVolumeMapper::PublishEmptyLayer(vtkRenderer* ren)
{
  int width = 0, height = 0, x0 = 0, y0 = 0;
  ren->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  width = std::max(width, 0);
  height = std::max(height, 0);
  vtkNew<vtkFloatArray> rgba;
  rgba->SetName("RGBA");
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  rgba->FillValue(0.0f);
  vtkImageData* image = this->GetFloatImage();
  image->SetDimensions(width, height, 1);
  image->GetPointData()->SetScalars(rgba);
  this->WitnessViolations = 0;
  this->NumberOfRenderedCells = this->NumberOfSkippedCells = 0;
  this->NumberOfSegments = this->NumberOfPieces = this->NumberOfRays = 0;
  this->NumberOfCellRecords = this->NumberOfTransparentCells = 0;
  this->NumberOfSplattedCells = 0;
  this->NumberOfProjectedTriangles = this->NumberOfProjectedSlabs = 0;
  vtkImageData* error = this->GetRayCastErrorImage(); // no error estimate for no cells
  error->SetDimensions(0, 0, 1);
  error->GetPointData()->Initialize();
  this->LastImageTime = 0.0;
  this->ShadingErrorEstimate = 0.0;
  this->LastRenderAborted = false;
}

double vtkPVHighOrderVolumeMapper::GetRayCastErrorEstimate()
{
  vtkImageData* image = this->GetRayCastErrorImage();
  vtkDataArray* error = image ? image->GetPointData()->GetArray("Error") : nullptr;
  if (this->GetRenderMode() != RAY_CAST || !error || error->GetNumberOfTuples() == 0)
  {
    return -1.0;
  }
  double range[2];
  error->GetRange(range, 0);
  return range[1];
}

std::string vtkPVHighOrderVolumeMapper::RankFileName() const
{
  int rank = 0, size = 1;
  RankAndSize(rank, size);
  if (size <= 1 || rank == 0)
  {
    return this->FloatImageFileName;
  }
  const std::string& name = this->FloatImageFileName;
  const size_t dot = name.rfind('.');
  const size_t slash = name.find_last_of("/\\");
  const size_t at = (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    ? name.size()
    : dot;
  std::ostringstream out;
  out << name.substr(0, at) << "_rank" << rank << name.substr(at);
  return out.str();
}

void vtkPVHighOrderVolumeMapper::WriteFloatImage()
{
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputData(this->GetFloatImage());
  const std::string name = this->RankFileName();
  writer->SetFileName(name.c_str());
  if (!writer->Write())
  {
    vtkErrorMacro("Could not write the float image to '" << name << "'.");
  }
}

void vtkPVHighOrderVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FloatImageFileName: " << this->FloatImageFileName << "\n";
  os << indent << "LastFrameTime: " << this->LastFrameTime << "\n";
  os << indent << "NumberOfRenderCalls: " << this->NumberOfRenderCalls << "\n";
}
