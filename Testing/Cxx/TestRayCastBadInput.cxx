// RAY_CAST bad input (issue 6 acceptance 5): a valid block of 48 linear
// tetrahedra plus cells the ray caster must skip, each reason counted in one
// warning, the rest rendered exactly as without them, no NaN pixel:
//  - unsupported types: Lagrange pyramid 74, Bezier pyramid 81, Lagrange
//    triangle 69 (a 2D cell), a second Lagrange pyramid with 14 nodes
//    (linear and quadratic pyramids, 14 and 27, are rendered: TestRayCastPyramid);
//  - an inverted (mirrored) order-2 Lagrange tetrahedron, curved;
//  - a tangled order-2 Lagrange tetrahedron (a mid-edge node pushed through
//    the opposite face: the Jacobian changes sign);
//  - a Lagrange tetrahedron with a NaN scalar and one with a NaN point.
// Then: cell scalars only (rendered since issue 19) and an input whose cells
// are all unsupported (a warning, an empty image).
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

using namespace hovTest;

namespace
{
/// An order-2 Lagrange tetrahedron (VTK node order: corners, then the edges
/// 01, 12, 20, 03, 13, 23) over corners @p c, mid-edge node 4 moved by @p bend.
void AddLagrangeTet2(MeshBuilder& m, const double c[4][3], const double bend[3], double s)
{
  static const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
  std::vector<vtkIdType> ids;
  for (int k = 0; k < 4; ++k)
  {
    ids.push_back(m.AddPoint(c[k][0], c[k][1], c[k][2], s));
  }
  for (int e = 0; e < 6; ++e)
  {
    double x[3];
    for (int r = 0; r < 3; ++r)
    {
      x[r] = 0.5 * (c[edges[e][0]][r] + c[edges[e][1]][r]) + (e == 0 ? bend[r] : 0.0);
    }
    ids.push_back(m.AddPoint(x[0], x[1], x[2], s));
  }
  m.AddCell(VTK_LAGRANGE_TETRAHEDRON, ids);
}
}

int TestRayCastBadInput(int, char*[])
{
  Checker ck;
  vtkNew<vtkCamera> cam;
  ObliqueCamera(cam);
  const MeshBuilder clean = UnitBlock(2);
  MeshBuilder bad = clean;
  // Bad cells far behind the block (x in [5, 6]): outside the view anyway.
  std::vector<vtkIdType> p;
  for (int k = 0; k < 5; ++k)
  {
    p.push_back(bad.AddPoint(5.0 + (k & 1), 5.0 + (k >> 1 & 1), k == 4 ? 6.0 : 5.0, 0.5));
  }
  bad.AddCell(VTK_LAGRANGE_PYRAMID, { p[0], p[1], p[3], p[2], p[4] });
  bad.AddCell(VTK_BEZIER_PYRAMID, { p[0], p[1], p[3], p[2], p[4] });
  bad.AddCell(VTK_LAGRANGE_TRIANGLE, { p[0], p[1], p[2] });
  {
    std::vector<vtkIdType> many(14, p[0]);
    std::copy(p.begin(), p.end(), many.begin());
    bad.AddCell(VTK_LAGRANGE_PYRAMID, many);
  }
  const double good[4][3] = { { 5, 5, 5 }, { 6, 5, 5 }, { 5, 6, 5 }, { 5, 5, 6 } };
  const double mirrored[4][3] = { { 5, 5, 5 }, { 5, 6, 5 }, { 6, 5, 5 }, { 5, 5, 6 } };
  const double curve[3] = { 0.0, -0.1, 0.0 }, through[3] = { 0.0, 1.5, 1.5 }, none[3] = { 0, 0, 0 };
  AddLagrangeTet2(bad, mirrored, curve, 0.5);
  AddLagrangeTet2(bad, good, through, 0.5);
  AddLagrangeTet2(bad, good, none, std::numeric_limits<double>::quiet_NaN());
  AddLagrangeTet2(bad, good, none, 0.5);
  const vtkIdType nanPoint = static_cast<vtkIdType>(bad.Points.size()) - 1;
  bad.Points[nanPoint][1] = std::numeric_limits<double>::quiet_NaN();

  VolumeScene ref(clean.Grid());
  DefaultTF(ref.Tf, 0.5);
  ref.Mapper->SetRenderModeToRayCast();
  const Image expected = Render(ref.Mapper, cam, ref.Volume, 48, 48);

  VolumeScene scene(bad.Grid());
  DefaultTF(scene.Tf, 0.5);
  scene.Mapper->SetRenderModeToRayCast();
  int status = 0;
  const Image img = Render(scene.Mapper, cam, scene.Volume, 48, 48, &status);
  const std::string warning = Msg(scene.Observer->GetWarningMessage());
  std::cout << "[measured] warning: '" << warning << "'\n";
  const Sanity s = CheckImage(img);
  const DiffStats d = Diff(expected, img);
  std::cout << "[measured] image " << s.Str() << "; vs clean block " << d.Str() << std::endl;
  ck.Check(status == 1 && !scene.Observer->GetError(), "bad cells: no error");
  ck.Check(warning.find("4 cells of types") != std::string::npos &&
      warning.find("first type: 74") != std::string::npos,
    "warning names the 4 unsupported cells and the first type");
  ck.Check(warning.find("2 with NaN/Inf") != std::string::npos, "warning counts 2 NaN cells");
  ck.Check(warning.find("2 inverted or degenerate") != std::string::npos,
    "warning counts the inverted and the tangled cell");
  ck.Check(scene.Mapper->GetNumberOfRenderedCells() == 48 &&
      scene.Mapper->GetNumberOfSkippedCells() == 8,
    "48 cells rendered, 8 skipped");
  ck.Check(s.Ok() && s.Covered > 0 && d.Count > 0 && d.Max == 0.0,
    "the rest renders exactly as the clean block, no NaN");

  // The same input again: no new warning (one per input).
  scene.Observer->Clear();
  Render(scene.Mapper, cam, scene.Volume, 48, 48);
  ck.Check(scene.NoMessages(), "second frame of the same input: no repeated warning");

  // Cell scalars only: rendered (issue 19; accuracy in TestRayCastCellScalars).
  vtkSmartPointer<vtkUnstructuredGrid> cellOnly = clean.Grid(false);
  vtkNew<vtkDoubleArray> cs;
  cs->SetNumberOfTuples(cellOnly->GetNumberOfCells());
  cs->Fill(0.5);
  cellOnly->GetCellData()->SetScalars(cs);
  VolumeScene cellScene(cellOnly);
  DefaultTF(cellScene.Tf, 0.5);
  cellScene.Mapper->SetRenderModeToRayCast();
  const Image cellImage = Render(cellScene.Mapper, cam, cellScene.Volume, 16, 16, &status);
  const Sanity se = CheckImage(cellImage);
  std::cout << "[measured] cell scalars: status " << status << ", " << se.Covered
            << " pixels covered\n";
  ck.Check(status == 1 && !cellScene.Observer->GetError() && se.Ok() && se.Covered > 0,
    "cell scalars: rendered, no error");

  // Only unsupported cells: a warning, nothing drawn, no error.
  MeshBuilder onlyBad;
  for (int k = 0; k < 5; ++k)
  {
    onlyBad.AddPoint(k & 1, k >> 1 & 1, k == 4 ? 1.0 : 0.0, 0.5);
  }
  onlyBad.AddCell(VTK_LAGRANGE_PYRAMID, { 0, 1, 3, 2, 4 });
  VolumeScene badScene(onlyBad.Grid());
  DefaultTF(badScene.Tf, 0.5);
  badScene.Mapper->SetRenderModeToRayCast();
  const Image none2 = Render(badScene.Mapper, cam, badScene.Volume, 16, 16, &status);
  const Sanity sn = CheckImage(none2);
  ck.Check(status == 1 && !badScene.Observer->GetError() && badScene.Observer->GetWarning() &&
      Msg(badScene.Observer->GetWarningMessage()).find("no usable cell") != std::string::npos &&
      sn.Ok() && sn.Covered == 0,
    "only unsupported cells: a warning, nothing drawn");
  return ck.Result();
}
