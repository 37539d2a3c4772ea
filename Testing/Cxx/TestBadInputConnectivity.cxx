// Malformed grids that VTK itself does not validate: a tetrahedron whose
// point id is out of range, and scalar arrays shorter than the number of
// points (or cells). The mapper promises that bad input never crashes: the
// bad cell must be skipped with a warning (in both cell orderings) and a short
// scalar array must be reported, never read past its end.
//
// (Kept apart from TestBadInputCells: a crash here must not hide the results
// of the other bad-input checks. Progress is flushed before every step so a
// crash shows where it happened; the step most likely to crash runs last.)
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVisibilitySort.h"

#include <iostream>
#include <string>

using namespace hovTest;

int TestBadInputConnectivity(int, char*[])
{
  Checker ck;
  VolumeScene scene;
  DefaultTF(scene.Tf);
  vtkNew<vtkCamera> cam;
  ObliqueCamera(cam);
  const int W = 64, H = 64;

  const MeshBuilder block = UnitBlock(2);
  auto blockGrid = block.Grid();
  Image ref[2];
  for (int o = 0; o < 2; ++o)
  {
    scene.Mapper->SetCellOrdering(o);
    scene.Mapper->SetInputData(blockGrid);
    ref[o] = Render(scene.Mapper, cam, scene.Volume, W, H);
  }

  // ---- Scalar arrays shorter than the points / cells they describe.
  // Renders @p g (whose short array is set) in CPU_ACCURATE and RAY_CAST, each
  // right after a valid frame of the block (so a count kept from it would
  // show): an error naming the array's size, status 0, a zero image of the
  // requested size, no rendered cell, no other message.
  auto renderShort = [&](vtkUnstructuredGrid* g, const std::string& what, bool cellScalars) {
    for (int mode : { vtkHighOrderVolumeMapper::CPU_ACCURATE, vtkHighOrderVolumeMapper::RAY_CAST })
    {
      const std::string label = what + (mode == vtkHighOrderVolumeMapper::RAY_CAST
                                            ? " (RAY_CAST)"
                                            : " (CPU_ACCURATE)");
      scene.Mapper->SetRenderMode(mode);
      scene.Mapper->SetScalarModeToDefault(); // the block has point scalars
      scene.Mapper->SetInputData(blockGrid);
      int status = -1;
      Render(scene.Mapper, cam, scene.Volume, W, H, &status);
      ck.Check(status == 1 && scene.Mapper->GetNumberOfRenderedCells() == 48,
        label + ": the block renders first");
      scene.Mapper->SetInputData(g);
      if (cellScalars)
      {
        scene.Mapper->SetScalarModeToUseCellData();
      }
      scene.Observer->Clear();
      status = -1;
      const Image img = Render(scene.Mapper, cam, scene.Volume, W, H, &status);
      const Sanity san = CheckImage(img);
      const std::string error = scene.Observer->GetErrorMessage();
      std::cout << "  " << label << ": status=" << status
                << " rendered=" << scene.Mapper->GetNumberOfRenderedCells() << " " << san.Str()
                << "\n  warning: '" << Msg(scene.Observer->GetWarningMessage()) << "' error: '"
                << Msg(error) << "'" << std::endl;
      ck.Check(scene.Observer->GetError() && error.find("tuples for") != std::string::npos,
        label + ": an error names the array's size (not read past its end)");
      ck.Check(!scene.Observer->GetWarning(), label + ": no warning besides the error");
      ck.Check(status == 0, label + ": RenderImage returns 0");
      ck.Check(scene.Mapper->GetNumberOfRenderedCells() == 0, label + ": no cell counted");
      ck.Check(san.Ok() && san.Covered == 0 && img.W == W && img.H == H,
        label + ": a zero image of the requested size");
    }
    scene.Mapper->SetRenderMode(vtkHighOrderVolumeMapper::CPU_ACCURATE);
    scene.Mapper->SetScalarModeToDefault();
  };
  {
    std::cout << "== point scalars with 2 tuples for " << block.Points.size()
              << " points: rendering..." << std::endl;
    auto g = block.Grid(false);
    vtkNew<vtkDoubleArray> s;
    s->SetName("short");
    s->SetNumberOfTuples(2);
    s->SetValue(0, 0.5);
    s->SetValue(1, 1.0);
    g->GetPointData()->SetScalars(s);
    scene.Mapper->SetCellOrderingToPerPixelSort();
    renderShort(g, "short point-scalar array", false);
  }
  {
    std::cout << "== cell scalars with 3 tuples for 48 cells: rendering..." << std::endl;
    auto g = block.Grid(false);
    vtkNew<vtkDoubleArray> s;
    s->SetName("shortcells");
    s->SetNumberOfTuples(3);
    for (int i = 0; i < 3; ++i)
    {
      s->SetValue(i, 0.5 * i);
    }
    g->GetCellData()->SetScalars(s);
    renderShort(g, "short cell-scalar array", true);
  }

  // ---- A tetrahedron with point id 100000 (the grid has 27 points).
  MeshBuilder broken = block;
  broken.AddCell(VTK_TETRA, { 0, 1, 2, 100000 });
  auto brokenGrid = broken.Grid();
  for (int o : { vtkHighOrderVolumeMapper::PER_PIXEL_SORT,
         vtkHighOrderVolumeMapper::VISIBILITY_SORT })
  {
    const char* name = o ? "PER_PIXEL_SORT" : "VISIBILITY_SORT";
    std::cout << "== point id out of range, " << name << ": rendering..." << std::endl;
    scene.Mapper->SetCellOrdering(o);
    scene.Mapper->SetInputData(brokenGrid);
    brokenGrid->Modified();
    scene.Observer->Clear();
    int status = -1;
    const Image img = Render(scene.Mapper, cam, scene.Volume, W, H, &status);
    const Sanity s = CheckImage(img);
    const DiffStats d = Diff(img, ref[o]);
    std::cout << "  status=" << status << " rendered=" << scene.Mapper->GetNumberOfRenderedCells()
              << " skipped=" << scene.Mapper->GetNumberOfSkippedCells() << " " << s.Str()
              << "\n  vs block alone: " << d.Str() << "\n  warning: '"
              << Msg(scene.Observer->GetWarningMessage()) << "' error: '"
              << Msg(scene.Observer->GetErrorMessage()) << "'" << std::endl;
    ck.Check(true, std::string(name) + ": no crash");
    ck.Check(scene.Observer->GetWarning() &&
        scene.Observer->GetWarningMessage().find("bad connectivity") != std::string::npos,
      std::string(name) + ": the bad cell is reported");
    ck.Check(scene.Mapper->GetNumberOfRenderedCells() == 48 &&
        scene.Mapper->GetNumberOfSkippedCells() == 1,
      std::string(name) + ": 48 rendered, 1 skipped");
    ck.Check(s.Ok() && d.Max <= 1e-6, std::string(name) + ": the valid tets render as alone");
  }

  // ---- VISIBILITY_SORT without a sort (SetVisibilitySort(nullptr)): an
  // error, status 0, a zero image and no empty-image warning.
  {
    std::cout << "== no visibility sort: rendering..." << std::endl;
    vtkSmartPointer<vtkVisibilitySort> sort = scene.Mapper->GetVisibilitySort();
    scene.Mapper->SetCellOrderingToVisibilitySort();
    scene.Mapper->SetInputData(blockGrid);
    scene.Mapper->SetVisibilitySort(nullptr);
    scene.Observer->Clear();
    int status = -1;
    const Image img = Render(scene.Mapper, cam, scene.Volume, W, H, &status);
    const Sanity san = CheckImage(img);
    std::cout << "  status=" << status << " " << san.Str() << "\n  warning: '"
              << Msg(scene.Observer->GetWarningMessage()) << "' error: '"
              << Msg(scene.Observer->GetErrorMessage()) << "'" << std::endl;
    ck.Check(scene.Observer->GetError() &&
        scene.Observer->GetErrorMessage().find("No visibility sort") != std::string::npos &&
        !scene.Observer->GetWarning(),
      "no sort: one error, no warning");
    ck.Check(status == 0 && san.Ok() && san.Covered == 0 && img.W == W,
      "no sort: status 0 and a zero image");
    scene.Mapper->SetVisibilitySort(sort);
  }

  return ck.Result();
}
