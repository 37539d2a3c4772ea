#include "hovRegression.h"

#include "vtkHighOrderImageComparison.h" // the strict comparison
#include "vtkHighOrderOffscreenWindow.h" // the window: X or Mesa EGL
#include "vtkHighOrderVolumeMapper.h" // the mapper under test

#include "hovThinSeries.h" // SetFusedSeries: "-separate-series"

#include "vtkCallbackCommand.h" // the mapper's warnings, printed without VTK's "ERROR:" header
#include "vtkCamera.h" // the default fit
#include "vtkColorTransferFunction.h" // the transfer function
#include "vtkDataArray.h" // the array's range
#include "vtkImageData.h" // the candidate image
#include "vtkNew.h" // owned objects
#include "vtkPNGReader.h" // the baseline, checked before VTK's comparison
#include "vtkPNGWriter.h" // the candidate and the difference image on failure
#include "vtkPiecewiseFunction.h" // the opacity function
#include "vtkPlane.h" // clipping planes
#include "vtkPointData.h" // the point array
#include "vtkRegressionTestImage.h" // VTK's comparison (vtkTesting, threshold 0.15)
#include "vtkRenderWindow.h" // the rendered window
#include "vtkRenderer.h" // the scene
#include "vtkSmartPointer.h" // the window from the factory
#include "vtkUnstructuredGrid.h" // the dataset
#include "vtkVolume.h" // the volume prop
#include "vtkVolumeProperty.h" // its property
#include "vtkWindowToImageFilter.h" // the capture
#include "vtkXMLUnstructuredGridReader.h" // reading the dataset
#include "vtksys/SystemTools.hxx" // file checks

#include <cmath>    // std::sqrt, std::ceil
#include <cstdlib>  // EXIT_SUCCESS, std::atof
#include <iostream> // messages

namespace hovRegression
{
namespace
{
/// highordervolume.render_tools.DEFAULT_NODES: fraction of the range, r, g, b, opacity.
const double Nodes[7][5] = { { 0.00, 0.15, 0.25, 0.90, 0.02 }, { 0.03, 0.20, 0.50, 1.00, 0.04 },
  { 0.09, 0.10, 0.90, 0.90, 0.10 }, { 0.20, 0.30, 1.00, 0.30, 0.25 },
  { 0.35, 1.00, 1.00, 0.10, 0.50 }, { 0.60, 1.00, 0.50, 0.00, 0.80 },
  { 1.00, 1.00, 0.05, 0.05, 1.00 } };

std::string ArgAfter(int argc, char* argv[], const char* flag, const std::string& fallback = "")
{
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == flag)
    {
      return argv[i + 1];
    }
  }
  return fallback;
}

/// VTK warnings of the mapper, printed as plain notes (tests may expect some,
/// e.g. curved quadratic cells drawn straight); errors still fail the test.
void PrintWarning(vtkObject*, unsigned long, void*, void* callData)
{
  std::cout << "note (mapper warning): " << static_cast<const char*>(callData) << "\n";
}

void SetupProperty(const Scene& scene, const double range[2], double diagonal, double perturb,
  vtkVolumeProperty* property)
{
  vtkNew<vtkColorTransferFunction> color;
  vtkNew<vtkPiecewiseFunction> opacity;
  for (const auto& n : Nodes)
  {
    const double s = range[0] + n[0] * (range[1] - range[0]);
    color->AddRGBPoint(s, n[1], n[2], n[3]);
    opacity->AddPoint(s, n[4]);
  }
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(scene.UnitFraction * diagonal * (1.0 + perturb));
  property->SetInterpolationTypeToLinear();
  property->ShadeOff();
}

void SetupMapper(const Scene& scene, const double range[2], const double bounds[6],
  vtkHighOrderVolumeMapper* mapper)
{
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectScalarArray(scene.Array.c_str());
  mapper->SetRenderMode(scene.RenderMode);
  mapper->SetOpacitySemantics(scene.Semantics);
  mapper->SetProjectionColorMethod(scene.ColorMethod);
  mapper->SetRayCastTolerance(scene.RayCastTolerance);
  for (size_t i = 0; i + 4 < scene.Isosurfaces.size(); i += 5)
  {
    const double* s = &scene.Isosurfaces[i];
    mapper->AddIsosurface(range[0] + s[0] * (range[1] - range[0]), s[1], s[2], s[3], s[4]);
  }
  for (size_t i = 0; i + 5 < scene.ClipPlanes.size(); i += 6)
  {
    const double* p = &scene.ClipPlanes[i];
    vtkNew<vtkPlane> plane;
    plane->SetOrigin(bounds[0] + p[0] * (bounds[1] - bounds[0]),
      bounds[2] + p[1] * (bounds[3] - bounds[2]), bounds[4] + p[2] * (bounds[5] - bounds[4]));
    plane->SetNormal(p[3], p[4], p[5]);
    mapper->AddClippingPlane(plane);
  }
}

/// The default fit of the comparison tools (render_tools.fit_camera): looking
/// along +y with z up, ResetCamera, then azimuth, elevation, zoom.
void SetupCamera(const Scene& scene, const double bounds[6], vtkRenderer* renderer)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(0, -1, 0);
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCamera(bounds);
  camera->Azimuth(scene.Azimuth);
  camera->Elevation(scene.Elevation);
  camera->OrthogonalizeViewUp();
  camera->Zoom(scene.Zoom);
  renderer->ResetCameraClippingRange(bounds);
}

bool WritePNG(vtkImageData* image, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
  return writer->GetErrorCode() == 0;
}

/// Writes the candidate to the temporary directory, says where; always false.
bool Reject(vtkImageData* candidate, const std::string& temp, const std::string& name,
  const std::string& why)
{
  const std::string path = temp + "/" + name + ".png";
  std::cout << "regression test " << name << " FAILED: " << why << "\n";
  if (WritePNG(candidate, path))
  {
    std::cout << "  candidate image written to " << path << "\n";
  }
  else
  {
    std::cout << "  cannot write the candidate image to " << path << "\n";
  }
  return false;
}

/// Baseline given, present, a PNG of @p width x @p height; @p problem otherwise.
bool BaselineUsable(const std::string& baseline, int width, int height, std::string& problem)
{
  if (baseline.empty())
  {
    problem = "no baseline given (-V <baseline.png>)";
    return false;
  }
  if (!vtksys::SystemTools::FileExists(baseline, true))
  {
    problem = "baseline '" + baseline + "' not found; check the candidate and copy it to " +
      "Testing/Data/Baseline/ under the test's name";
    return false;
  }
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(baseline.c_str()))
  {
    problem = "baseline '" + baseline + "' is not a PNG file";
    return false;
  }
  reader->SetFileName(baseline.c_str());
  reader->Update();
  int b[3];
  reader->GetOutput()->GetDimensions(b);
  if (b[0] != width || b[1] != height)
  {
    problem = "baseline '" + baseline + "' is " + std::to_string(b[0]) + " x " +
      std::to_string(b[1]) + " pixels, the rendered image " + std::to_string(width) + " x " +
      std::to_string(height) + " (the test's size changed, or the wrong baseline: regenerate it)";
    return false;
  }
  return true;
}

bool StrictCompare(const std::string& baseline, vtkImageData* candidate, int renderMode,
  const std::string& temp, const std::string& name)
{
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(baseline.c_str());
  reader->Update();
  const Allowance allowance = Tolerance(renderMode);
  int dims[3];
  candidate->GetDimensions(dims);
  vtkNew<vtkHighOrderImageComparison> comparison;
  comparison->SetTolerance(allowance.Levels);
  comparison->SetAllowedPixels(
    static_cast<vtkIdType>(std::floor(allowance.PixelFraction * dims[0] * dims[1])));
  const bool passed = comparison->Compare(reader->GetOutput(), candidate);
  std::cout << "strict comparison (at most " << allowance.Levels << "/255 per pixel, at most "
            << comparison->GetAllowedPixels() << " pixels differing): "
            << comparison->GetSummary() << "\n";
  if (!passed)
  {
    Reject(candidate, temp, name, "strict comparison failed");
    if (comparison->GetDifferenceImage() &&
      WritePNG(comparison->GetDifferenceImage(), temp + "/" + name + ".strict-diff.png"))
    {
      std::cout << "  difference image (x" << comparison->GetDifferenceScale()
                << ", red: beyond the tolerance) written to " << temp << "/" << name
                << ".strict-diff.png\n";
    }
  }
  return passed;
}
}

//------------------------------------------------------------------------------
Allowance Tolerance(int renderMode)
{
  // Measured (README, "Regression tests"): X and EGL give the same images; an
  // older CPU's code paths (llvmpipe at 128 bits and SSE4.1, glibc's libm
  // without FMA/AVX2) change nothing in the CPU modes and at most 4 pixels by
  // one level in OPENGL_PROJECTION.
  Allowance a;
  if (renderMode == vtkHighOrderVolumeMapper::OPENGL_PROJECTION)
  {
    a.Levels = 1;
    a.PixelFraction = 0.002;
  }
  return a; // CPU_ACCURATE, RAY_CAST: identical images
}

int Run(int argc, char* argv[], const Scene& scene)
{
  const std::string data = ArgAfter(argc, argv, "-data");
  // The baseline and the temporary directory as VTK's comparison resolves them
  // (-V relative to the data root -D, -T or VTK_TEMP_DIR).
  vtkNew<vtkTesting> testing;
  testing->AddArguments(argc, argv);
  const std::string temp = testing->GetTempDirectory();
  const std::string baseline =
    testing->IsValidImageSpecified() ? testing->GetValidImageFileName() : "";
  const double perturb = std::atof(ArgAfter(argc, argv, "-perturb", "0").c_str());
  // "-separate-series": the thin series rounded as on a CPU without FMA
  // (hovThinSeries.h), to check that such a CPU reproduces the baselines.
  bool separateSeries = false;
  for (int i = 1; i < argc; ++i)
  {
    separateSeries = separateSeries || std::string(argv[i]) == "-separate-series";
  }
  if (separateSeries)
  {
    hov::detail::SetFusedSeries(false);
  }

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  if (data.empty() || !vtksys::SystemTools::FileExists(data, true))
  {
    std::cout << scene.Name << ": no dataset (-data '" << data << "')\n";
    return EXIT_FAILURE;
  }
  reader->SetFileName(data.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  vtkDataArray* array = grid->GetPointData()->GetArray(scene.Array.c_str());
  if (grid->GetNumberOfCells() == 0 || !array)
  {
    std::cout << scene.Name << ": no cells or no point array '" << scene.Array << "' in " << data
              << "\n";
    return EXIT_FAILURE;
  }
  double range[2], bounds[6];
  array->GetRange(range, 0);
  grid->GetBounds(bounds);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));

  vtkNew<vtkHighOrderVolumeMapper> mapper;
  mapper->SetInputData(grid);
  SetupMapper(scene, range, bounds, mapper);
  vtkNew<vtkCallbackCommand> warnings;
  warnings->SetCallback(PrintWarning);
  mapper->AddObserver(vtkCommand::WarningEvent, warnings);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  SetupProperty(scene, range, diagonal, perturb, volume->GetProperty());
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.1);
  renderer->AddVolume(volume);
  SetupCamera(scene, bounds, renderer);

  vtkNew<vtkHighOrderOffscreenWindow> factory;
  vtkSmartPointer<vtkRenderWindow> window =
    vtkSmartPointer<vtkRenderWindow>::Take(factory->NewRenderWindow(scene.Width, scene.Height));
  if (!window)
  {
    std::cout << scene.Name << ": no render window: " << factory->GetErrorMessage() << "\n";
    return EXIT_FAILURE;
  }
  std::cout << scene.Name << ": " << scene.Width << " x " << scene.Height << ", render window "
            << factory->GetBackendName() << " (" << window->GetClassName() << ")"
            << (perturb != 0.0 ? ", unit distance perturbed by " + std::to_string(perturb) : "")
            << ", thin series " << (hov::detail::FusedSeries() ? "fused" : "separate") << "\n";
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);

  // The frame compared is the one vtkRegressionTestImage renders and reads:
  // vtkWindowToImageFilter renders again with a copy of the camera, whose
  // matrices, rebuilt from position, focal point and view up, can differ from
  // the original's in the last bits (OPENGL_PROJECTION then moves a few pixels
  // by one level). A candidate written without a usable baseline is rendered
  // the same way, so that it is exactly what the comparisons will see.
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->SetInputBufferTypeToRGB();
  capture->ReadFrontBufferOff();
  vtkImageData* candidate = capture->GetOutput();

  std::string problem;
  if (!BaselineUsable(baseline, scene.Width, scene.Height, problem))
  {
    window->SwapBuffersOff();
    window->Render();
    capture->ShouldRerenderOn();
    capture->Update();
    Reject(candidate, temp, scene.Name, problem);
    return EXIT_FAILURE;
  }

  // VTK's comparison (renders, reads the back buffer; on failure it writes the
  // candidate and its difference image to -T), then ours on the same frame.
  const int vtkResult = vtkRegressionTestImage(window);
  std::cout << "\nVTK's comparison (vtkRegressionTestImage, threshold 0.15): "
            << (vtkResult == vtkTesting::PASSED ? "passed" : "FAILED") << "\n";
  capture->ShouldRerenderOff();
  capture->Update();
  const bool strict = StrictCompare(baseline, candidate, scene.RenderMode, temp, scene.Name);
  return vtkResult == vtkTesting::PASSED && strict ? EXIT_SUCCESS : EXIT_FAILURE;
}
}
