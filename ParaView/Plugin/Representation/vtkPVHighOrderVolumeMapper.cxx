#include "vtkPVHighOrderVolumeMapper.h"

#include "vtkDataArray.h"               // the error estimate
#include "vtkImageData.h"               // the float image
#include "vtkMultiProcessController.h"  // the rank in file names
#include "vtkObjectFactory.h"           // vtkStandardNewMacro
#include "vtkPointData.h"               // the error estimate
#include "vtkTimerLog.h"                // frame time
#include "vtkUnstructuredGridBase.h"    // the piece
#include "vtkXMLImageDataWriter.h"      // float image file

#include <sstream> // file names

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
    timer->StopTimer();
    this->LastFrameTime = timer->GetElapsedTime();
    return;
  }
  this->Superclass::Render(ren, vol);
  timer->StopTimer();
  this->LastFrameTime = timer->GetElapsedTime();
  if (!this->FloatImageFileName.empty())
  {
    this->WriteFloatImage();
  }
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
