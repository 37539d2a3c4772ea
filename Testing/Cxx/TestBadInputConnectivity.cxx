// Malformed grids that VTK itself does not validate: a tetrahedron whose
// point id is out of range, and scalar arrays shorter than the number of
// points (or cells). The mapper promises that bad input never crashes: the
// bad cell must be skipped with a warning (in both cell orderings) and a short
// scalar array must be reported, never read past its end.
//
// (Kept apart from TestBadInputCells: a crash here must not hide the results
// of the other bad-input checks. Progress is flushed before every step so a
// crash shows where it happened; the step most likely to crash runs last.)
#include "hovTestMeshes2.h"

#include "vtkCellData.h"
#include "vtkTestErrorObserver.h"

#include <iostream>

using namespace hovTest2;

int TestBadInputConnectivity(int, char*[])
{
  Checker ck;
  vtkNew<vtkHighOrderVolumeMapper> mapper;
  TF tf;
  DefaultTF(tf);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(tf.Property);
  vtkNew<vtkCamera> cam;
  ObliqueCamera(cam);
  vtkNew<vtkTest::ErrorObserver> obs;
  mapper->AddObserver(vtkCommand::ErrorEvent, obs);
  mapper->AddObserver(vtkCommand::WarningEvent, obs);
  const int W = 64, H = 64;

  const MeshBuilder block = UnitBlock(2);
  auto blockGrid = block.Grid();
  Image ref[2];
  for (int o = 0; o < 2; ++o)
  {
    mapper->SetCellOrdering(o);
    mapper->SetInputData(blockGrid);
    ref[o] = Render(mapper, cam, volume, W, H);
  }

  // ---- Scalar arrays shorter than the points / cells they describe.
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
    mapper->SetCellOrderingToPerPixelSort();
    mapper->SetInputData(g);
    obs->Clear();
    int status = -1;
    const Image img = Render(mapper, cam, volume, W, H, &status);
    const Sanity san = CheckImage(img);
    std::cout << "  status=" << status << " rendered=" << mapper->GetNumberOfRenderedCells() << " "
              << san.Str() << "\n  warning: '" << Msg(obs->GetWarningMessage()) << "' error: '"
              << Msg(obs->GetErrorMessage()) << "'" << std::endl;
    ck.Check(obs->GetError() || obs->GetWarning(),
      "short point-scalar array: reported (not read past its end)");
    ck.Check(san.Ok(), "short point-scalar array: sane image");
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
    mapper->SetScalarModeToUseCellData();
    mapper->SetInputData(g);
    obs->Clear();
    int status = -1;
    const Image img = Render(mapper, cam, volume, W, H, &status);
    const Sanity san = CheckImage(img);
    std::cout << "  status=" << status << " rendered=" << mapper->GetNumberOfRenderedCells() << " "
              << san.Str() << "\n  warning: '" << Msg(obs->GetWarningMessage()) << "' error: '"
              << Msg(obs->GetErrorMessage()) << "'" << std::endl;
    ck.Check(obs->GetError() || obs->GetWarning(),
      "short cell-scalar array: reported (not read past its end)");
    ck.Check(san.Ok(), "short cell-scalar array: sane image");
    mapper->SetScalarModeToDefault();
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
    mapper->SetCellOrdering(o);
    mapper->SetInputData(brokenGrid);
    brokenGrid->Modified();
    obs->Clear();
    int status = -1;
    const Image img = Render(mapper, cam, volume, W, H, &status);
    const Sanity s = CheckImage(img);
    const DiffStats d = Diff(img, ref[o]);
    std::cout << "  status=" << status << " rendered=" << mapper->GetNumberOfRenderedCells()
              << " skipped=" << mapper->GetNumberOfSkippedCells() << " " << s.Str()
              << "\n  vs block alone: " << d.Str() << "\n  warning: '"
              << Msg(obs->GetWarningMessage()) << "' error: '" << Msg(obs->GetErrorMessage())
              << "'" << std::endl;
    ck.Check(true, std::string(name) + ": no crash");
    ck.Check(obs->GetWarning() &&
        obs->GetWarningMessage().find("bad connectivity") != std::string::npos,
      std::string(name) + ": the bad cell is reported");
    ck.Check(mapper->GetNumberOfRenderedCells() == 48 && mapper->GetNumberOfSkippedCells() == 1,
      std::string(name) + ": 48 rendered, 1 skipped");
    ck.Check(s.Ok() && d.Max <= 1e-6, std::string(name) + ": the valid tets render as alone");
  }

  return ck.Result();
}
