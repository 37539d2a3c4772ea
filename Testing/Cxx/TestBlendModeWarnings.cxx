// Blend-mode settings and their messages (issue 19): AverageIPScalarRange's
// default and Set/Get; an unsupported blend mode (ADDITIVE 4, SLICE 6, 42)
// gives one warning naming it per change of the setting and renders as
// COMPOSITE_BLEND (the same float image); isosurfaces with MIP give one
// warning (ignored: the image is the plain MIP image); back to composite and
// a supported mode: no message. CPU_ACCURATE and RAY_CAST.
#include "hovTestScenes.h"

#include "vtkCamera.h"

#include <iostream>

namespace
{
constexpr int N = 24;
}

int TestBlendModeWarnings(int, char*[])
{
  hovTest::Checker check;
  hovTest::VolumeScene scene(hovTest::UnitBlock(2).Grid());
  hovTest::DefaultTF(scene.Tf, 0.5);
  vtkNew<vtkCamera> cam;
  hovTest::ObliqueCamera(cam);
  vtkHighOrderVolumeMapper* mapper = scene.Mapper;
  const double* range = mapper->GetAverageIPScalarRange();
  check.Check(range[0] == VTK_FLOAT_MIN && range[1] == VTK_FLOAT_MAX,
    "AverageIPScalarRange defaults to [VTK_FLOAT_MIN, VTK_FLOAT_MAX]");
  mapper->SetAverageIPScalarRange(0.1, 0.9);
  check.Check(mapper->GetAverageIPScalarRange()[0] == 0.1 &&
      mapper->GetAverageIPScalarRange()[1] == 0.9,
    "SetAverageIPScalarRange / Get");
  for (int mode = 0; mode <= 2; mode += 2)
  {
    mapper->SetRenderMode(mode);
    const std::string name = mode == 0 ? "CPU_ACCURATE" : "RAY_CAST";
    mapper->SetBlendModeToComposite();
    const hovTest::Image composite = hovTest::Render(mapper, cam, scene.Volume, N, N);
    for (int bad : { 4, 6, 42 })
    {
      scene.Observer->Clear();
      mapper->SetBlendMode(bad);
      const hovTest::Image img = hovTest::Render(mapper, cam, scene.Volume, N, N);
      const std::string warning = hovTest::Msg(scene.Observer->GetWarningMessage());
      std::cout << "[measured] " << name << ", blend mode " << bad << ": '" << warning << "'\n";
      check.Check(scene.Observer->GetWarning() &&
          warning.find(bad == 42 ? "value 42" : std::to_string(bad)) != std::string::npos &&
          warning.find("rendered as COMPOSITE_BLEND") != std::string::npos,
        name + ": blend mode " + std::to_string(bad) + " is named in one warning");
      check.Check(hovTest::Diff(img, composite).Max == 0.0,
        name + ": blend mode " + std::to_string(bad) + " renders as composite");
      scene.Observer->Clear();
      hovTest::Render(mapper, cam, scene.Volume, N, N);
      check.Check(scene.NoMessages(), name + ": the same setting again: no repeated warning");
    }
    mapper->SetBlendModeToMaximumIntensity();
    scene.Observer->Clear();
    const hovTest::Image mip = hovTest::Render(mapper, cam, scene.Volume, N, N);
    check.Check(scene.NoMessages() && hovTest::Diff(mip, composite).Max > 0.01,
      name + ": MIP, no message, an image other than composite");
    mapper->AddIsosurface(0.8, 1, 1, 1, 0.5);
    const hovTest::Image withIso = hovTest::Render(mapper, cam, scene.Volume, N, N);
    const std::string warning = hovTest::Msg(scene.Observer->GetWarningMessage());
    std::cout << "[measured] " << name << ", MIP + isosurface: '" << warning << "'\n";
    check.Check(scene.Observer->GetWarning() && warning.find("Isosurfaces") != std::string::npos,
      name + ": isosurfaces with MIP: one warning");
    check.Check(hovTest::Diff(withIso, mip).Max == 0.0, name + ": the isosurface is ignored");
    scene.Observer->Clear();
    hovTest::Render(mapper, cam, scene.Volume, N, N);
    check.Check(scene.NoMessages(), name + ": no repeated warning");
    mapper->RemoveAllIsosurfaces();
    mapper->SetBlendModeToComposite();
    hovTest::Render(mapper, cam, scene.Volume, N, N);
    check.Check(scene.NoMessages(), name + ": back to composite: no message");
  }
  return check.Result();
}
