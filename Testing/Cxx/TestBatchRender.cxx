// hovBatchRender (Utilities/Batch) reproduces the C++ API's float image bit
// for bit: the bundled bracket rendered here with vtkHighOrderVolumeMapper
// (explicit perspective camera, per-pixel ordering, a clipping plane,
// VTK-unstructured semantics) and by the executable from the equivalent spec
// (written here), then the .vti read back and compared value by value. A
// spec with a wrong camera arity must exit with code 2, name the field and
// write nothing. The executable is <build>/bin/hovBatchRender (found from
// the "-T" folder <build>/Testing/Temporary).
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLImageDataReader.h"

#include <cstdio>  // std::remove
#include <cstdlib> // std::system
#include <fstream>
#include <string>
#include <sys/wait.h> // WEXITSTATUS

using namespace hovTest;

namespace
{
const char* SpecText = R"({
  "data": "%DATA%",
  "array": {"name": "von_mises"},
  "image": {"width": 90, "height": 70},
  "camera": {"position": [200, -140, 190], "focal_point": [50, 30, 40], "view_up": [0, 0, 1],
             "view_angle": 32},
  "transfer_function": {"color": [[0, 0.1, 0.1, 1], [80, 1, 1, 1], [170, 1, 0.1, 0.1]],
                        "opacity": [[0, 0.05], [80, 0.4], [170, 0.9]], "unit_distance": 2,
                        "opacity_semantics": "vtk_unstructured"},
  "clipping": {"planes": [{"origin": [60, 30, 40], "normal": [-1, 0, 0.3]}]},
  "cell_ordering": "per_pixel_sort",
  "output": {"vti": "%OUT%"}
})";

std::string Replace(std::string s, const std::string& key, const std::string& value)
{
  const size_t at = s.find(key);
  return at == std::string::npos ? s : s.replace(at, key.size(), value);
}

int RunBatch(const std::string& exe, const std::string& spec, const std::string& log)
{
  const std::string command = "\"" + exe + "\" \"" + spec + "\" > \"" + log + "\" 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string ReadText(const std::string& path)
{
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}
}

int TestBatchRender(int argc, char* argv[])
{
  Checker ck;
  std::string file;
  auto grid = LoadBracket(argc, argv, &file);
  const std::string tmp = ArgAfter(argc, argv, "-T", ".");
  const std::string exe = tmp + "/../../bin/hovBatchRender";
  if (!ck.Check(grid != nullptr && std::ifstream(exe).good(), "bracket and " + exe + " found"))
  {
    return ck.Result();
  }

  // The C++ API with the spec's settings.
  VolumeScene scene(grid);
  vtkHighOrderVolumeMapper* mapper = scene.Mapper;
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectScalarArray("von_mises");
  mapper->SetOpacitySemanticsToVTKUnstructured();
  mapper->SetCellOrderingToPerPixelSort();
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(60, 30, 40);
  plane->SetNormal(-1, 0, 0.3);
  mapper->AddClippingPlane(plane);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 0.1, 0.1, 1);
  color->AddRGBPoint(80, 1, 1, 1);
  color->AddRGBPoint(170, 1, 0.1, 0.1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.05);
  opacity->AddPoint(80, 0.4);
  opacity->AddPoint(170, 0.9);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(2);
  property->SetInterpolationTypeToLinear();
  property->IndependentComponentsOff();
  scene.Volume->SetProperty(property);
  vtkNew<vtkRenderer> renderer;
  vtkCamera* cam = renderer->GetActiveCamera();
  cam->SetViewUp(0, 0, 1);
  cam->SetFocalPoint(50, 30, 40);
  cam->SetPosition(200, -140, 190);
  cam->SetViewUp(0, 0, 1);
  cam->SetViewAngle(32);
  renderer->ResetCameraClippingRange(grid->GetBounds());
  const Image api = Render(mapper, cam, scene.Volume, 90, 70);

  // The executable.
  const std::string vti = tmp + "/TestBatchRender.vti", spec = tmp + "/TestBatchRender.json";
  std::remove(vti.c_str());
  std::ofstream(spec) << Replace(Replace(SpecText, "%DATA%", file), "%OUT%", vti);
  const int code = RunBatch(exe, spec, tmp + "/TestBatchRender.log");
  vtkNew<vtkXMLImageDataReader> reader;
  vtkFloatArray* rgba = nullptr;
  if (std::ifstream(vti).good())
  {
    reader->SetFileName(vti.c_str());
    reader->Update();
    rgba = vtkFloatArray::SafeDownCast(reader->GetOutput()->GetPointData()->GetArray("RGBA"));
  }
  size_t differing = 0, covered = 0;
  const bool sized = rgba && rgba->GetNumberOfValues() == static_cast<vtkIdType>(api.V.size());
  for (size_t k = 0; sized && k < api.V.size(); ++k)
  {
    differing += static_cast<double>(rgba->GetValue(k)) != api.V[k];
    covered += k % 4 == 3 && api.V[k] > 0.01;
  }
  ck.Check(code == 0 && sized && differing == 0 && covered > 500,
    "hovBatchRender exit " + std::to_string(code) + ", " + std::to_string(differing) +
      " values differ from the C++ API image (" + std::to_string(covered) + " covered pixels)");

  // A malformed spec: exit 2, the field named, no output.
  std::remove(vti.c_str());
  std::ofstream(spec) << Replace(Replace(Replace(SpecText, "%DATA%", file), "%OUT%", vti),
    "[200, -140, 190]", "[200, -140]");
  const int bad = RunBatch(exe, spec, tmp + "/TestBatchRender.log");
  const std::string log = ReadText(tmp + "/TestBatchRender.log");
  ck.Check(bad == 2 && log.find("camera.position: expected 3 numbers, got 2") != std::string::npos &&
      !std::ifstream(vti).good(),
    "malformed spec: exit " + std::to_string(bad) + ", message: " + log);
  ck.Check(scene.NoMessages(), "no error or warning");
  return ck.Result();
}
