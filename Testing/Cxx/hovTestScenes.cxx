#include "hovTestScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkHighOrderOffscreenWindow.h" // windows with X (Xvfb) or without (Mesa EGL)
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <cstdlib>
#include <iostream>
#include <sstream>

namespace hovTest
{
//------------------------------------------------------------------------------
bool Checker::Check(bool ok, const std::string& what)
{
  ++this->Checks;
  if (!ok)
  {
    ++this->Failures;
    std::cout << "  FAILED: " << what << "\n";
  }
  else
  {
    std::cout << "  ok: " << what << "\n";
  }
  return ok;
}

int Checker::Result() const
{
  std::cout << this->Checks << " checks, " << this->Failures << " failed\n";
  return this->Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

const char* ModeName(int mode)
{
  switch (mode)
  {
    case vtkHighOrderVolumeMapper::OPENGL_PROJECTION:
      return "OPENGL_PROJECTION";
    case vtkHighOrderVolumeMapper::RAY_CAST:
      return "RAY_CAST";
    default:
      return "CPU_ACCURATE";
  }
}

std::string Msg(const std::string& raw)
{
  std::string out, line;
  std::istringstream in(raw);
  while (std::getline(in, line))
  {
    if (line.empty() || line.rfind("ERROR: In ", 0) == 0 || line.rfind("Warning: In ", 0) == 0 ||
      line.rfind("Generic Warning: In ", 0) == 0)
    {
      continue;
    }
    const size_t k = line.find("): ");
    if (!out.empty())
    {
      out += " | ";
    }
    out += k != std::string::npos ? line.substr(k + 3) : line;
  }
  // Never echo the markers ctest looks for.
  for (const char* marker : { "ERROR:", "ERR|" })
  {
    size_t k;
    while ((k = out.find(marker)) != std::string::npos)
    {
      out.replace(k, 3, "Err");
    }
  }
  return out;
}

std::string ArgAfter(int argc, char* argv[], const char* flag, const std::string& fallback)
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

void ObserveMessages(vtkObject* object, vtkCommand* observer)
{
  object->AddObserver(vtkCommand::ErrorEvent, observer);
  object->AddObserver(vtkCommand::WarningEvent, observer);
}

//------------------------------------------------------------------------------
TF::TF()
{
  this->Property->SetColor(this->Color);
  this->Property->SetScalarOpacity(this->Opacity);
  this->Property->SetInterpolationTypeToLinear();
  this->Property->ShadeOff();
}

void DefaultTF(TF& tf, double unit)
{
  tf.Color->RemoveAllPoints();
  tf.Color->AddRGBPoint(0.0, 1.0, 0.1, 0.1);
  tf.Color->AddRGBPoint(0.9, 0.1, 1.0, 0.2);
  tf.Color->AddRGBPoint(1.75, 0.1, 0.2, 1.0);
  tf.Opacity->RemoveAllPoints();
  tf.Opacity->AddPoint(0.0, 0.2);
  tf.Opacity->AddPoint(0.6, 0.7);
  tf.Opacity->AddPoint(1.0, 0.3);
  tf.Opacity->AddPoint(1.75, 0.8);
  tf.Property->SetScalarOpacityUnitDistance(unit);
}

void ConstantTF(TF& tf, const double rgb[3], double opacity, double unit)
{
  tf.Color->AddRGBPoint(0.0, rgb[0], rgb[1], rgb[2]);
  tf.Opacity->AddPoint(0.0, opacity);
  tf.Property->SetScalarOpacityUnitDistance(unit);
}

void BracketTF(TF& tf, double unit)
{
  // s, r, g, b, opacity
  const double nodes[5][5] = { { 0.0, 0.10, 0.20, 0.90, 0.03 }, { 8.0, 0.10, 0.80, 0.80, 0.10 },
    { 30.0, 0.30, 0.90, 0.20, 0.30 }, { 80.0, 0.95, 0.80, 0.10, 0.60 },
    { 170.0, 0.90, 0.10, 0.10, 0.90 } };
  for (const auto& nd : nodes)
  {
    tf.Color->AddRGBPoint(nd[0], nd[1], nd[2], nd[3]);
    tf.Opacity->AddPoint(nd[0], nd[4]);
  }
  tf.Property->SetScalarOpacityUnitDistance(unit);
}

//------------------------------------------------------------------------------
VolumeScene::VolumeScene(vtkUnstructuredGrid* input)
{
  this->Volume->SetMapper(this->Mapper);
  this->Volume->SetProperty(this->Tf.Property);
  ObserveMessages(this->Mapper, this->Observer);
  if (input)
  {
    this->Mapper->SetInputData(input);
  }
}

void LinearShadingTF(TF& tf, double sA, double sB, const double colorA[3],
  const double colorB[3], double opacityA, double opacityB, double ka, double kd, double ks,
  double power)
{
  tf.Color->RemoveAllPoints();
  tf.Color->AddRGBPoint(sA, colorA[0], colorA[1], colorA[2]);
  tf.Color->AddRGBPoint(sB, colorB[0], colorB[1], colorB[2]);
  tf.Opacity->RemoveAllPoints();
  tf.Opacity->AddPoint(sA, opacityA);
  tf.Opacity->AddPoint(sB, opacityB);
  tf.Property->SetScalarOpacityUnitDistance(1.0);
  tf.Property->SetAmbient(ka);
  tf.Property->SetDiffuse(kd);
  tf.Property->SetSpecular(ks);
  tf.Property->SetSpecularPower(power);
}

void MessageCounter::Execute(vtkObject*, unsigned long event, void* data)
{
  (event == vtkCommand::WarningEvent ? this->Warnings : this->Errors)++;
  this->Text += static_cast<const char*>(data);
}

void MessageCounter::Clear()
{
  this->Warnings = this->Errors = 0;
  this->Text.clear();
}

bool VolumeScene::NoMessages() const
{
  return !this->Observer->GetError() && !this->Observer->GetWarning();
}

bool VolumeScene::NoMessagesBut(const std::string& allowed) const
{
  const std::string w = this->Observer->GetWarningMessage();
  const size_t first = w.find("Warning");
  return !this->Observer->GetError() &&
    (!this->Observer->GetWarning() ||
      (w.find(allowed) != std::string::npos &&
        w.find("Warning", first == std::string::npos ? 0 : first + 1) == std::string::npos));
}

//------------------------------------------------------------------------------
void ObliqueCamera(vtkCamera* cam)
{
  cam->SetFocalPoint(0.5, 0.5, 0.5);
  cam->SetPosition(2.6, 1.9, 3.1);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(30);
  cam->ParallelProjectionOff();
  cam->SetClippingRange(0.5, 20);
}

void AxisOrthoCamera(vtkCamera* cam, double scale, double dx)
{
  cam->SetFocalPoint(0.5 + dx, 0.5, 0.5);
  cam->SetPosition(0.5 + dx, 0.5, 5.0);
  cam->SetViewUp(0, 1, 0);
  cam->ParallelProjectionOn();
  cam->SetParallelScale(scale);
  cam->SetClippingRange(1.0, 10.0);
}

double OrthoPixelCoord(int i, int n, double scale, double aspect, double dx)
{
  return 0.5 + dx + (2.0 * (i + 0.5) / n - 1.0) * scale * aspect;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkRenderer> BlackRenderer(vtkCamera* cam)
{
  auto ren = vtkSmartPointer<vtkRenderer>::New();
  ren->SetBackground(0, 0, 0);
  ren->SetActiveCamera(cam);
  return ren;
}

vtkSmartPointer<vtkRenderWindow> OffscreenWindow(vtkRenderer* ren, int w, int h, int multiSamples)
{
  vtkNew<vtkHighOrderOffscreenWindow> factory;
  auto win = vtkSmartPointer<vtkRenderWindow>::Take(factory->NewRenderWindow(w, h));
  if (!win)
  {
    std::cout << "no render window: " << factory->GetErrorMessage() << "\n";
    std::exit(EXIT_FAILURE);
  }
  if (multiSamples >= 0)
  {
    win->SetMultiSamples(multiSamples);
  }
  if (ren)
  {
    win->AddRenderer(ren);
  }
  win->SetSize(w, h);
  return win;
}

CPUAndProjection RenderCPUAndProjectionM3(vtkHighOrderVolumeMapper* mapper, vtkRenderWindow* win)
{
  CPUAndProjection out;
  mapper->SetRenderModeToCPUAccurate();
  win->Render();
  out.CPU = FloatImage(mapper);
  mapper->SetRenderModeToOpenGLProjection();
  mapper->SetProjectionColorMethod(vtkHighOrderVolumeMapper::EXACT_COLOR);
  win->Render();
  out.Projection = FloatImage(mapper);
  return out;
}

vtkSmartPointer<vtkActor> BoxActor(const double b[6], const double rgb[3], double opacity)
{
  // (Built by hand: vtkCubeSource's module is not linked into the tests.)
  vtkNew<vtkPoints> pts;
  for (int k = 0; k < 8; ++k)
  {
    pts->InsertNextPoint(b[(k & 1) ? 1 : 0], b[(k & 2) ? 3 : 2], b[(k & 4) ? 5 : 4]);
  }
  vtkNew<vtkCellArray> quads;
  const vtkIdType faces[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  for (const auto& f : faces)
  {
    quads->InsertNextCell(4, f);
  }
  vtkNew<vtkPolyData> box;
  box->SetPoints(pts);
  box->SetPolys(quads);
  vtkNew<vtkPolyDataMapper> pm;
  pm->SetInputData(box);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(pm);
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetOpacity(opacity);
  return actor;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> LoadBracket(int argc, char* argv[], std::string* file)
{
  const std::string path = ArgAfter(argc, argv, "-D", ".") + "/bracket_tet4_ccx.vtu";
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
  grid->GetPointData()->SetActiveScalars("von_mises");
  if (file)
  {
    *file = path;
  }
  return grid;
}

std::unique_ptr<VolumeScene> BracketScene(Checker& ck, int argc, char* argv[])
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = LoadBracket(argc, argv);
  if (!ck.Check(grid != nullptr, "bracket loaded"))
  {
    return nullptr;
  }
  auto scene = std::make_unique<VolumeScene>(grid);
  BracketTF(scene->Tf, 2.0);
  scene->Volume->SetProperty(scene->Tf.Property);
  return scene;
}

void BracketCamera(vtkCamera* cam)
{
  cam->SetFocalPoint(50, 30, 40);
  cam->SetPosition(50 + 160, 30 + 120, 40 + 200);
  cam->SetViewUp(0, 0, 1);
  cam->SetClippingRange(50, 600);
}

Image NonInteractiveRender(vtkRenderWindow* win, vtkHighOrderVolumeMapper* mapper)
{
  const double progressive = mapper->GetProgressiveTime();
  const bool autoAdjust = mapper->GetAutoAdjustImageSampleDistance();
  mapper->AutoAdjustImageSampleDistanceOff();
  mapper->SetProgressiveTime(0.0);
  win->SetDesiredUpdateRate(0.0001);
  win->Render();
  Image ref = FloatImage(mapper);
  mapper->SetAutoAdjustImageSampleDistance(autoAdjust);
  mapper->SetProgressiveTime(progressive);
  return ref;
}
}
