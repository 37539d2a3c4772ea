// The accurate CPU path with its default order (vtkSteinVisibilitySort,
// CellOrdering VISIBILITY_SORT) against vtkCellCenterDepthSort and
// PER_PIXEL_SORT, through HIAC's z-buffer witness and the float image.
//  - Meshes and views where VISIBILITY_SORT with vtkCellCenterDepthSort makes
//    the witness fire (> 0 pixels out of order): the bundled bracket in
//    oblique views, a holed block seen from inside its hole, a log pile.
//  - There the default mapper (Stein) must read 0 and its image must equal
//    the PER_PIXEL_SORT image (each pixel's segments sorted by entry: exact)
//    to 1e-6 per channel.
//  - The cyclic triple (as tetrahedra): the sort reports a cycle, the mapper
//    warns once and renders that frame per pixel: witness 0, image equal to
//    PER_PIXEL_SORT.
#include "hovSortMeshes.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCellCenterDepthSort.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkSteinVisibilitySort.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>

using namespace hovTest;

namespace
{
struct Row
{
  vtkIdType WitnessCenter = 0, WitnessStein = 0, WitnessPixel = 0;
  double MaxDiff = 0;
  size_t Covered = 0;
};

Row Compare(VolumeScene& scene, vtkCamera* cam, int size)
{
  Row r;
  vtkHighOrderVolumeMapper* m = scene.Mapper;
  vtkSmartPointer<vtkVisibilitySort> stein = m->GetVisibilitySort();
  m->SetCellOrderingToVisibilitySort();
  vtkNew<vtkCellCenterDepthSort> center;
  m->SetVisibilitySort(center);
  Render(m, cam, scene.Volume, size, size);
  r.WitnessCenter = m->GetWitnessViolations();
  m->SetVisibilitySort(stein);
  const Image s = Render(m, cam, scene.Volume, size, size);
  r.WitnessStein = m->GetWitnessViolations();
  m->SetCellOrderingToPerPixelSort();
  const Image p = Render(m, cam, scene.Volume, size, size);
  r.WitnessPixel = m->GetWitnessViolations();
  m->SetCellOrderingToVisibilitySort();
  r.MaxDiff = Diff(s, p, 0, 4).Max;
  r.Covered = CheckImage(p).Covered;
  return r;
}

void Print(const std::string& name, const Row& r)
{
  std::cout << "  " << std::left << std::setw(36) << name << std::right << std::setw(9)
            << r.Covered << std::setw(14) << r.WitnessCenter << std::setw(14) << r.WitnessStein
            << std::setw(12) << r.WitnessPixel << std::setw(16) << Fmt(r.MaxDiff) << "\n";
}

void Camera(vtkCamera* cam, const double pos[3], const double focal[3], double angle)
{
  cam->SetPosition(pos);
  cam->SetFocalPoint(focal);
  cam->SetViewUp(0, 0, 1);
  if (std::abs(pos[0] - focal[0]) < 1e-9 && std::abs(pos[1] - focal[1]) < 1e-9)
  {
    cam->SetViewUp(0, 1, 0);
  }
  cam->SetViewAngle(angle);
  const double* p = pos;
  double d = std::sqrt((p[0] - focal[0]) * (p[0] - focal[0]) + (p[1] - focal[1]) * (p[1] - focal[1]) +
    (p[2] - focal[2]) * (p[2] - focal[2]));
  cam->SetClippingRange(1e-3 * d, 100 * d);
}
}

int TestSortWitness(int argc, char* argv[])
{
  Checker ck;
  std::cout << "  " << std::left << std::setw(36) << "mesh, view" << std::right << std::setw(9)
            << "covered" << std::setw(14) << "witness ctr" << std::setw(14) << "witness Stein"
            << std::setw(12) << "witness PP" << std::setw(16) << "max|Stein-PP|" << "\n";
  {
    vtkNew<vtkHighOrderVolumeMapper> fresh;
    ck.Check(fresh->GetCellOrdering() == vtkHighOrderVolumeMapper::VISIBILITY_SORT &&
        vtkSteinVisibilitySort::SafeDownCast(fresh->GetVisibilitySort()) != nullptr,
      "defaults: VISIBILITY_SORT with a vtkSteinVisibilitySort");
  }
  vtkIdType centerTotal = 0;
  auto run = [&](const std::string& name, VolumeScene& scene, vtkCamera* cam, int size) {
    const Row r = Compare(scene, cam, size);
    Print(name, r);
    centerTotal += r.WitnessCenter;
    ck.Check(r.WitnessStein == 0 && r.WitnessPixel == 0, name + ": Stein witness 0 (centre sort: " +
        std::to_string(r.WitnessCenter) + ")");
    ck.Check(r.MaxDiff <= 1e-6, name + ": Stein image = PER_PIXEL_SORT image (max " +
        Fmt(r.MaxDiff) + ")");
    ck.Check(r.Covered > 0.05 * size * size, name + ": the mesh covers > 5% of the image");
    return r;
  };

  // The bracket (oblique view of TestWitness).
  vtkSmartPointer<vtkUnstructuredGrid> bracket = LoadBracket(argc, argv);
  {
    VolumeScene scene(bracket);
    BracketTF(scene.Tf, 3.0);
    vtkNew<vtkCamera> cam;
    const double pos[3] = { 160, 120, 180 }, focal[3] = { 50, 30, 40 };
    Camera(cam, pos, focal, 40);
    cam->SetViewUp(0, 1, 0);
    const Row r = run("bracket, oblique (+110,+90,+140)", scene, cam, 160);
    ck.Check(r.WitnessCenter > 0, "bracket: vtkCellCenterDepthSort makes the witness fire");
    ck.Check(scene.NoMessages(), "bracket: no messages");
  }
  // A holed block seen from inside its hole, and from outside.
  {
    VolumeScene scene(HoledBlock(7, 31));
    DefaultTF(scene.Tf, 0.3);
    vtkNew<vtkCamera> cam;
    const double e1[3] = { 0.5, 0.48, 0.55 }, f1[3] = { 0.9, 0.6, 0.15 };
    Camera(cam, e1, f1, 70);
    run("holed block, inside the hole", scene, cam, 120);
    const double e2[3] = { 2.2, -1.1, 1.9 }, f2[3] = { 0.5, 0.5, 0.5 };
    Camera(cam, e2, f2, 30);
    run("holed block, oblique outside", scene, cam, 120);
    ck.Check(scene.NoMessages(), "holed block: no messages");
  }
  ck.Check(centerTotal > 0, "vtkCellCenterDepthSort's witness fires somewhere (" +
      std::to_string(centerTotal) + " pixels)");

  // The cyclic triple: per-pixel fallback.
  {
    VolumeScene scene(CyclicTripleTets());
    DefaultTF(scene.Tf, 0.05); // colour varies between the sticks: the order matters
    vtkNew<vtkCamera> cam;
    const double pos[3] = { 0, 0, 6 }, focal[3] = { 0, 0, 0 };
    Camera(cam, pos, focal, 35);
    scene.Observer->Clear();
    const Image s = Render(scene.Mapper, cam, scene.Volume, 128, 128);
    const vtkIdType witness = scene.Mapper->GetWitnessViolations();
    const std::string warning = Msg(scene.Observer->GetWarningMessage());
    auto* stein = vtkSteinVisibilitySort::SafeDownCast(scene.Mapper->GetVisibilitySort());
    const vtkIdType cycles = stein ? stein->GetNumberOfCycles() : -1;
    scene.Observer->Clear();
    Render(scene.Mapper, cam, scene.Volume, 128, 128); // same frame again: no second warning
    const bool warnedTwice = scene.Observer->GetWarning();
    scene.Mapper->SetCellOrderingToPerPixelSort();
    const Image p = Render(scene.Mapper, cam, scene.Volume, 128, 128);
    const double d = Diff(s, p, 0, 4).Max;
    std::cout << "  cyclic triple (9 tets): cycles " << cycles << ", witness " << witness
              << ", max|img - PP| " << Fmt(d) << ", covered " << CheckImage(p).Covered
              << ", warning '" << warning << "'\n";
    ck.Check(cycles > 0, "cyclic triple: the Stein sort reports a cycle");
    ck.Check(warning.find("cycle") != std::string::npos && !warnedTwice,
      "cyclic triple: the mapper warns once about the cycle");
    ck.Check(witness == 0 && d <= 1e-12 && CheckImage(p).Covered > 100,
      "cyclic triple: the frame is rendered per pixel (witness 0, image = PER_PIXEL_SORT)");
  }
  return ck.Result();
}
