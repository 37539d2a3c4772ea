/**
 * @file   hovBatchRender.cxx
 * @brief  hovBatchRender spec.json: render an image specification file with vtkHighOrderVolumeMapper.
 *
 * Reads and checks the spec (hovBatchSpec.h; any error: the messages on
 * stderr, exit code 2, nothing rendered), reads the data set, sets up the
 * camera (vtkRenderer::ResetCamera on the data bounds at the image aspect,
 * unless position and focal point are given; then view angle, azimuth,
 * elevation, roll, zoom, parallel scale; then ResetCameraClippingRange), and
 * renders: CPU_ACCURATE through RenderImage (no window at all),
 * OPENGL_PROJECTION in an off-screen render window from
 * vtkHighOrderOffscreenWindow (X if DISPLAY is set, Mesa EGL if not). Writes the float
 * premultiplied RGBA image (.vti, array "RGBA") and/or a PNG (the image over
 * the background colour, 8-bit RGB). Progress is printed on stderr. The
 * Python twin (highordervolume.batch) makes the same calls in the same order.
 *
 * Exit codes: 0 only when the render reported no error and every requested
 * output was written (checked on disk); 2 for a spec that is not valid (the
 * messages name the field); 1 for a render error or an output that could not
 * be written.
 */
#include "hovBatchSpec.h"

#include "vtkHighOrderOffscreenWindow.h" // the window of OPENGL_PROJECTION, with or without X
#include "vtkHighOrderVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCallbackCommand.h" // progress
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLImageDataWriter.h"
#include "vtkXMLUnstructuredGridReader.h"
#include "vtkUnstructuredGridReader.h"

#include <algorithm> // std::min
#include <cmath>     // std::lround
#include <cstdio>    // std::remove
#include <fstream>   // data file check
#include <iostream>  // messages

namespace
{
/// True if @p path exists and is not empty (the writers report some failures
/// only in their messages: vtkXMLWriter::Write() returns 1 for a missing folder).
bool Written(const std::string& path)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  return in && in.tellg() > 0;
}

vtkSmartPointer<vtkUnstructuredGrid> ReadData(const std::string& path)
{
  const bool legacy = path.size() > 4 && path.compare(path.size() - 4, 4, ".vtk") == 0;
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  if (legacy)
  {
    vtkNew<vtkUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    grid = reader->GetOutput();
  }
  else
  {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    grid = reader->GetOutput();
  }
  return grid && grid->GetNumberOfCells() > 0 ? grid : nullptr;
}

void SetupProperty(const hov::BatchSpec& spec, vtkVolumeProperty* property)
{
  vtkNew<vtkColorTransferFunction> color;
  for (size_t i = 0; i + 3 < spec.ColorNodes.size(); i += 4)
  {
    color->AddRGBPoint(
      spec.ColorNodes[i], spec.ColorNodes[i + 1], spec.ColorNodes[i + 2], spec.ColorNodes[i + 3]);
  }
  vtkNew<vtkPiecewiseFunction> opacity;
  for (size_t i = 0; i + 1 < spec.OpacityNodes.size(); i += 2)
  {
    opacity->AddPoint(spec.OpacityNodes[i], spec.OpacityNodes[i + 1]);
  }
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(spec.UnitDistance);
  property->SetInterpolationTypeToLinear();
  property->IndependentComponentsOff(); // one array component: component 0's functions
  property->ShadeOff();
}

void SetupMapper(const hov::BatchSpec& spec, vtkHighOrderVolumeMapper* mapper)
{
  if (spec.CellArray)
  {
    mapper->SetScalarModeToUseCellFieldData();
  }
  else
  {
    mapper->SetScalarModeToUsePointFieldData();
  }
  mapper->SelectScalarArray(spec.ArrayName.c_str());
  if (spec.ArrayComponent >= 0)
  {
    mapper->SetVectorMode(vtkHighOrderVolumeMapper::COMPONENT);
    mapper->SetVectorComponent(spec.ArrayComponent);
  }
  mapper->SetOpacitySemantics(spec.OpacitySemantics);
  mapper->SetGPUOpacityTolerance(spec.GPUOpacityTolerance);
  mapper->SetEmissionModel(spec.EmissionModel);
  mapper->SetEmissionScale(spec.EmissionScale);
  mapper->SetIntegrationMethod(spec.Integration);
  mapper->SetCellOrdering(spec.CellOrdering);
  mapper->SetRenderMode(spec.RenderMode);
  mapper->SetRayCastTolerance(spec.RayCastTolerance);
  for (size_t i = 0; i + 4 < spec.Isosurfaces.size(); i += 5)
  {
    const double* s = &spec.Isosurfaces[i];
    mapper->AddIsosurface(s[0], s[1], s[2], s[3], s[4]);
  }
  for (size_t i = 0; i + 5 < spec.ClipPlanes.size(); i += 6)
  {
    vtkNew<vtkPlane> plane;
    plane->SetOrigin(spec.ClipPlanes[i], spec.ClipPlanes[i + 1], spec.ClipPlanes[i + 2]);
    plane->SetNormal(spec.ClipPlanes[i + 3], spec.ClipPlanes[i + 4], spec.ClipPlanes[i + 5]);
    mapper->AddClippingPlane(plane);
  }
  if (spec.ViewDepthClipping)
  {
    mapper->SetViewDepthClipping(true);
    mapper->SetViewDepthRange(spec.ViewDepthRange);
  }
}

void SetupCamera(const hov::BatchSpec& spec, const double bounds[6], vtkRenderer* renderer)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetParallelProjection(spec.Orthographic);
  camera->SetViewUp(spec.ViewUp);
  if (spec.HasPosition)
  {
    camera->SetFocalPoint(spec.FocalPoint);
    camera->SetPosition(spec.Position);
    camera->SetViewUp(spec.ViewUp);
  }
  else
  {
    // The default fit, at the image aspect (no window: set it by hand).
    // Looking down -z; along +y if the view up is (nearly) the z axis.
    const double* up = spec.ViewUp;
    const double upNorm = std::sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
    const bool zUp = upNorm > 0.0 && std::abs(up[2]) > 0.999 * upNorm;
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(0.0, zUp ? -1.0 : 0.0, zUp ? 0.0 : 1.0);
    renderer->SetAspect(static_cast<double>(spec.Width) / spec.Height, 1.0);
    renderer->ResetCamera(bounds);
  }
  if (spec.HasViewAngle)
  {
    camera->SetViewAngle(spec.ViewAngle);
  }
  if (spec.HasAzimuth)
  {
    camera->Azimuth(spec.Azimuth);
  }
  if (spec.HasElevation)
  {
    camera->Elevation(spec.Elevation);
    camera->OrthogonalizeViewUp();
  }
  if (spec.HasRoll)
  {
    camera->Roll(spec.Roll);
  }
  if (spec.HasZoom)
  {
    camera->Zoom(spec.Zoom);
  }
  if (spec.HasParallelScale)
  {
    camera->SetParallelScale(spec.ParallelScale);
  }
  renderer->ResetCameraClippingRange(bounds);
}

bool WritePNG(const hov::BatchSpec& spec, vtkImageData* image)
{
  vtkFloatArray* rgba = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("RGBA"));
  vtkNew<vtkImageData> png;
  png->SetDimensions(spec.Width, spec.Height, 1);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(static_cast<vtkIdType>(spec.Width) * spec.Height);
  for (vtkIdType i = 0; rgba && i < rgb->GetNumberOfTuples(); ++i)
  {
    const float* p = rgba->GetPointer(4 * i);
    for (int k = 0; k < 3; ++k)
    {
      const double v = p[k] + (1.0 - p[3]) * spec.Background[k];
      rgb->SetValue(3 * i + k,
        static_cast<unsigned char>(std::lround(255.0 * std::min(1.0, std::max(0.0, v)))));
    }
  }
  png->GetPointData()->SetScalars(rgb);
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(spec.OutputPNG.c_str());
  writer->SetInputData(png);
  std::remove(spec.OutputPNG.c_str()); // an old file must not pass for the new one
  writer->Write();
  return writer->GetErrorCode() == 0 && Written(spec.OutputPNG);
}

void PrintProgress(vtkObject*, unsigned long, void*, void* callData)
{
  const double done = *static_cast<double*>(callData);
  std::cerr << "\rprogress " << static_cast<int>(100.0 * done + 0.5) << "%" << (done >= 1.0 ? "\n" : "")
            << std::flush;
}

/// Prints the mapper's errors (an observer stops VTK from printing them) and counts them.
void CountError(vtkObject*, unsigned long, void* clientData, void* callData)
{
  ++*static_cast<int*>(clientData);
  std::cerr << "error: " << (callData ? static_cast<const char*>(callData) : "") << "\n";
}

/// Render and write; returns the exit code (0 only when every requested
/// output was written from a render without errors).
int Render(const hov::BatchSpec& spec, vtkUnstructuredGrid* grid)
{
  vtkNew<vtkHighOrderVolumeMapper> mapper;
  mapper->SetInputData(grid);
  int errors = 0;
  vtkNew<vtkCallbackCommand> errorCount;
  errorCount->SetCallback(CountError);
  errorCount->SetClientData(&errors);
  mapper->AddObserver(vtkCommand::ErrorEvent, errorCount);
  SetupMapper(spec, mapper);
  vtkNew<vtkCallbackCommand> progress;
  progress->SetCallback(PrintProgress);
  mapper->AddObserver(vtkCommand::ProgressEvent, progress);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  SetupProperty(spec, volume->GetProperty());
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(spec.Background[0], spec.Background[1], spec.Background[2]);
  SetupCamera(spec, grid->GetBounds(), renderer);
  if (spec.RenderMode != vtkHighOrderVolumeMapper::OPENGL_PROJECTION) // the CPU modes
  {
    if (!mapper->RenderImage(renderer->GetActiveCamera(), volume, spec.Width, spec.Height))
    {
      std::cerr << "render failed (see the messages above)\n";
      return 1;
    }
  }
  else
  {
    // X if DISPLAY is set, Mesa EGL if not; a message instead of VTK's abort.
    vtkNew<vtkHighOrderOffscreenWindow> factory;
    vtkSmartPointer<vtkRenderWindow> window =
      vtkSmartPointer<vtkRenderWindow>::Take(factory->NewRenderWindow(spec.Width, spec.Height));
    if (!window)
    {
      std::cerr << "render window: " << factory->GetErrorMessage() << "\n";
      return 1;
    }
    window->AddRenderer(renderer);
    renderer->AddVolume(volume);
    window->Render();
  }
  if (errors > 0)
  {
    std::cerr << "render failed (see the messages above)\n";
    return 1;
  }
  vtkImageData* image = mapper->GetFloatImage();
  if (!spec.OutputVTI.empty())
  {
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetFileName(spec.OutputVTI.c_str());
    writer->SetInputData(image);
    std::remove(spec.OutputVTI.c_str()); // an old file must not pass for the new one
    if (!writer->Write() || writer->GetErrorCode() != 0 || !Written(spec.OutputVTI))
    {
      std::cerr << "output.vti: cannot write '" << spec.OutputVTI << "'\n";
      return 1;
    }
  }
  if (!spec.OutputPNG.empty() && !WritePNG(spec, image))
  {
    std::cerr << "output.png: cannot write '" << spec.OutputPNG << "'\n";
    return 1;
  }
  return 0;
}
}

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: hovBatchRender spec.json\n";
    return 2;
  }
  hov::BatchSpec spec;
  std::vector<std::string> errors, warnings;
  const bool ok = hov::ReadBatchSpec(argv[1], spec, errors, warnings);
  for (const std::string& w : warnings)
  {
    std::cerr << argv[1] << ": warning: " << w << "\n";
  }
  for (const std::string& e : errors)
  {
    std::cerr << argv[1] << ": error: " << e << "\n";
  }
  if (!ok)
  {
    return 2;
  }
  if (!std::ifstream(spec.Data))
  {
    std::cerr << argv[1] << ": error: data: cannot read '" << spec.Data << "'\n";
    return 2;
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid = ReadData(spec.Data);
  if (!grid)
  {
    std::cerr << argv[1] << ": error: data: no cells read from '" << spec.Data << "'\n";
    return 2;
  }
  vtkDataArray* array = spec.CellArray ? grid->GetCellData()->GetArray(spec.ArrayName.c_str())
                                       : grid->GetPointData()->GetArray(spec.ArrayName.c_str());
  if (!array)
  {
    std::cerr << argv[1] << ": error: array.name: no " << (spec.CellArray ? "cell" : "point")
              << " array '" << spec.ArrayName << "' in '" << spec.Data << "'\n";
    return 2;
  }
  if (spec.ArrayComponent >= array->GetNumberOfComponents())
  {
    std::cerr << argv[1] << ": error: array.component: " << spec.ArrayComponent << " but '"
              << spec.ArrayName << "' has " << array->GetNumberOfComponents() << " components\n";
    return 2;
  }
  return Render(spec, grid);
}
