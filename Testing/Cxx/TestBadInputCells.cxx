// Bad cells and bad arrays: no scalars, string arrays, NaN/Inf scalars and
// points, degenerate and inverted tetrahedra, empty grids, unsupported cell
// types. For each: no crash, an error or warning where the input is bad (none
// where it is fine), a finite float image with 0 <= alpha <= 1, and the valid
// tetrahedra render exactly as they do alone (within 1e-6).
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

using namespace hovTest;

namespace
{
const double NaN = std::numeric_limits<double>::quiet_NaN();
const double Inf = std::numeric_limits<double>::infinity();
constexpr int W = 96, H = 80;

const char* OrderName(int o)
{
  return o == vtkHighOrderVolumeMapper::PER_PIXEL_SORT ? "PER_PIXEL_SORT" : "VISIBILITY_SORT";
}

/// A loose tetrahedron inside the unit block (overlapping it), vertices moved by @p d.
void LooseTetPoints(double p[4][3], double d)
{
  const double q[4][3] = { { 0.25, 0.2, 0.3 }, { 0.75, 0.25, 0.2 }, { 0.3, 0.8, 0.25 },
    { 0.35, 0.3, 0.85 } };
  for (int i = 0; i < 4; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      p[i][c] = q[i][c] + d;
    }
  }
}
}

int TestBadInputCells(int, char*[])
{
  Checker ck;
  VolumeScene scene;
  DefaultTF(scene.Tf);
  vtkNew<vtkCamera> cam;
  ObliqueCamera(cam);
  cam->SetViewAngle(40);

  const int orders[2] = { vtkHighOrderVolumeMapper::PER_PIXEL_SORT,
    vtkHighOrderVolumeMapper::VISIBILITY_SORT };

  // Render @p grid in one ordering; the grid is marked modified so the mapper
  // re-validates it and reports its problems again.
  auto render = [&](vtkUnstructuredGrid* grid, int order, int& status) {
    scene.Mapper->SetCellOrdering(order);
    scene.Mapper->SetInputData(grid);
    grid->Modified();
    scene.Observer->Clear();
    return Render(scene.Mapper, cam, scene.Volume, W, H, &status);
  };

  // ---- Reference: the valid block alone (48 tets), in both orderings.
  const MeshBuilder block = UnitBlock(2);
  auto blockGrid = block.Grid();
  Image ref[2];
  vtkIdType refWitness[2];
  std::cout << "== reference: unit block of " << block.Cells.size() << " positive tets, " << W
            << "x" << H << "\n";
  for (int o = 0; o < 2; ++o)
  {
    int status = 0;
    ref[o] = render(blockGrid, orders[o], status);
    refWitness[o] = scene.Mapper->GetWitnessViolations();
    const Sanity s = CheckImage(ref[o]);
    std::cout << "  " << OrderName(orders[o]) << ": " << s.Str()
              << " witness=" << refWitness[o] << "\n";
    ck.Check(status == 1, "valid block renders (RenderImage returns 1)");
    ck.Check(scene.NoMessages(),
      "no error or warning for a valid block; got: '" + Msg(scene.Observer->GetErrorMessage()) +
        Msg(scene.Observer->GetWarningMessage()) + "'");
    ck.Check(s.Ok() && s.Covered > 1000, "reference image is sane and covers > 1000 pixels");
    ck.Check(scene.Mapper->GetNumberOfRenderedCells() == 48 &&
        scene.Mapper->GetNumberOfSkippedCells() == 0,
      "48 rendered, 0 skipped");
  }
  const DiffStats refOrders = Diff(ref[0], ref[1]);
  std::cout << "  PER_PIXEL vs VISIBILITY on the block: " << refOrders.Str() << "\n";

  // Common verdict for a grid = valid part + bad cells.
  auto badCase = [&](const std::string& name, vtkUnstructuredGrid* grid, const Image* refs,
                   const std::string& warnText, vtkIdType rendered, vtkIdType skipped) {
    std::cout << "== " << name << " (" << grid->GetNumberOfCells() << " cells)\n";
    for (int o = 0; o < 2; ++o)
    {
      int status = 0;
      const Image img = render(grid, orders[o], status);
      const Sanity s = CheckImage(img);
      const DiffStats d = Diff(img, refs[o]);
      std::cout << "  " << OrderName(orders[o]) << ": status=" << status
                << " rendered=" << scene.Mapper->GetNumberOfRenderedCells()
                << " skipped=" << scene.Mapper->GetNumberOfSkippedCells()
                << " witness=" << scene.Mapper->GetWitnessViolations() << "\n    " << s.Str()
                << "\n    vs valid cells alone: " << d.Str() << "\n    warning: '"
                << Msg(scene.Observer->GetWarningMessage()) << "' error: '"
                << Msg(scene.Observer->GetErrorMessage()) << "'\n";
      ck.Check(status == 1, name + ": RenderImage returns 1 (bad cells are not an error)");
      ck.Check(!scene.Observer->GetError(), name + ": no error");
      ck.Check(scene.Observer->GetWarning() &&
          scene.Observer->GetWarningMessage().find(warnText) != std::string::npos,
        name + ": a warning containing '" + warnText + "'");
      ck.Check(s.Ok(), name + ": finite image, 0 <= alpha <= 1, 0 <= rgb <= alpha");
      ck.Check(scene.Mapper->GetNumberOfRenderedCells() == rendered &&
          scene.Mapper->GetNumberOfSkippedCells() == skipped,
        name + ": " + std::to_string(rendered) + " rendered, " + std::to_string(skipped) +
          " skipped");
      ck.Check(d.Max <= 1e-6,
        name + " (" + OrderName(orders[o]) + "): image equals the valid cells alone within 1e-6 (max " +
          Fmt(d.Max) + ")");
    }
  };

  // ---- 1. No scalars at all.
  {
    std::cout << "== no scalars\n";
    auto grid = block.Grid(false);
    int status = -1;
    const Image img = render(grid, orders[0], status);
    const Sanity s = CheckImage(img);
    std::cout << "  status=" << status << " " << s.Str() << "\n  error: '"
              << Msg(scene.Observer->GetErrorMessage()) << "'\n";
    ck.Check(scene.Observer->GetError(), "no scalars: an error is reported");
    ck.Check(img.W == W && img.H == H && s.Ok() && s.Covered == 0 && s.MaxRGB == 0.0,
      "no scalars: a zero image of the requested size");
    ck.Check(status == 0,
      "no scalars: RenderImage returns 0 (documented: '0 on error'; missing scalars are an error)");
    std::cout << "  diagnostics after the failed render: rendered="
              << scene.Mapper->GetNumberOfRenderedCells()
              << " skipped=" << scene.Mapper->GetNumberOfSkippedCells()
              << " (the previous render had 48)\n";
    ck.Check(scene.Mapper->GetNumberOfRenderedCells() == 0,
      "no scalars: GetNumberOfRenderedCells() describes this render (0), not the previous one");
  }

  // ---- 2. String arrays.
  {
    vtkNew<vtkStringArray> names;
    names->SetName("names");
    names->SetNumberOfValues(static_cast<vtkIdType>(block.Points.size()));
    for (vtkIdType i = 0; i < names->GetNumberOfValues(); ++i)
    {
      names->SetValue(i, "p" + std::to_string(i));
    }
    // (a) a string array as the only point array.
    auto only = block.Grid(false);
    only->GetPointData()->AddArray(names);
    std::cout << "== a vtkStringArray as the only point array (default scalar mode)\n";
    int status = -1;
    Image img = render(only, orders[0], status);
    Sanity s = CheckImage(img);
    std::cout << "  status=" << status << " " << s.Str() << "\n  error: '"
              << Msg(scene.Observer->GetErrorMessage()) << "'\n";
    ck.Check(scene.Observer->GetError(), "string-only: an error is reported");
    ck.Check(s.Ok() && s.Covered == 0, "string-only: zero image");

    // (b) selected by name, next to a valid numeric array.
    auto both = block.Grid(true);
    both->GetPointData()->AddArray(names);
    scene.Mapper->SetScalarModeToUsePointFieldData();
    scene.Mapper->SelectScalarArray("names");
    std::cout << "== SelectScalarArray(\"names\") (a vtkStringArray) with numeric 's' present\n";
    img = render(both, orders[0], status);
    s = CheckImage(img);
    std::cout << "  status=" << status << " " << s.Str() << "\n  error: '"
              << Msg(scene.Observer->GetErrorMessage()) << "'\n";
    ck.Check(scene.Observer->GetError(), "selected string array: an error is reported");
    ck.Check(s.Ok() && s.Covered == 0,
      "selected string array: zero image (the numeric array is not silently used)");
    ck.Check(status == 0, "selected string array: RenderImage returns 0 (documented: '0 on error')");

    // (c) a missing name.
    scene.Mapper->SelectScalarArray("no_such_array");
    img = render(both, orders[0], status);
    s = CheckImage(img);
    std::cout << "== SelectScalarArray(\"no_such_array\"): status=" << status << " " << s.Str()
              << " error: '" << Msg(scene.Observer->GetErrorMessage()) << "'\n";
    ck.Check(scene.Observer->GetError() && s.Ok() && s.Covered == 0,
      "missing array: error and zero image");

    // (d) the numeric array by name renders like the default scalars.
    scene.Mapper->SelectScalarArray("s");
    img = render(both, orders[0], status);
    const DiffStats d = Diff(img, ref[0]);
    std::cout << "== SelectScalarArray(\"s\"): status=" << status << " vs default scalars "
              << d.Str() << "\n";
    ck.Check(status == 1 && scene.NoMessages() && d.Max <= 1e-12,
      "selecting the numeric array by name renders the reference");
    scene.Mapper->SetScalarModeToDefault();
  }

  // ---- 3a. NaN / +Inf / -Inf point scalars on loose tets overlapping the block.
  {
    const double bad[3] = { NaN, Inf, -Inf };
    MeshBuilder m = block;
    for (int k = 0; k < 3; ++k)
    {
      double p[4][3];
      LooseTetPoints(p, 0.05 * k);
      const double sv[4] = { 0.4, bad[k], 0.9, 1.2 };
      m.AddLooseTet(p, sv);
    }
    badCase("NaN/+Inf/-Inf point scalars (3 loose tets)", m.Grid(), ref, "with NaN/Inf scalars",
      48, 3);
    // Control: the same tets with finite scalars change the image.
    MeshBuilder c = block;
    for (int k = 0; k < 3; ++k)
    {
      double p[4][3];
      LooseTetPoints(p, 0.05 * k);
      const double sv[4] = { 0.4, 1.0, 0.9, 1.2 };
      c.AddLooseTet(p, sv);
    }
    int status;
    auto cg = c.Grid();
    const Image img = render(cg, orders[0], status);
    const DiffStats d = Diff(img, ref[0]);
    std::cout << "  control (same tets, finite scalars): vs block alone " << d.Str()
              << " witness(overlap)=" << scene.Mapper->GetWitnessViolations() << "\n";
    ck.Check(d.Max > 1e-2, "control: the loose tets are visible when their scalars are finite");
  }

  // ---- 3b. NaN / Inf cell scalars inside the block.
  {
    const vtkIdType badCells[4] = { 5, 17, 30, 41 };
    const double badValues[4] = { NaN, Inf, -Inf, NaN };
    auto cellScalars = [&](const MeshBuilder& m, const std::vector<vtkIdType>& keep) {
      vtkNew<vtkDoubleArray> a;
      a->SetName("c");
      for (vtkIdType id : keep)
      {
        double s = 0;
        for (vtkIdType v : m.Cells[id])
        {
          s += DefaultField(m.Points[v][0], m.Points[v][1], m.Points[v][2]) / 4;
        }
        for (int k = 0; k < 4; ++k)
        {
          if (badCells[k] == id)
          {
            s = badValues[k];
          }
        }
        a->InsertNextValue(s);
      }
      return vtkSmartPointer<vtkDoubleArray>(a.Get());
    };
    std::vector<vtkIdType> all, good;
    for (vtkIdType i = 0; i < 48; ++i)
    {
      all.push_back(i);
      if (std::find(badCells, badCells + 4, i) == badCells + 4)
      {
        good.push_back(i);
      }
    }
    auto full = block.Grid();
    full->GetCellData()->SetScalars(cellScalars(block, all));
    MeshBuilder g = block;
    g.Cells.clear();
    g.Types.clear();
    for (vtkIdType id : good)
    {
      g.AddCell(VTK_TETRA, block.Cells[id]);
    }
    auto valid = g.Grid();
    valid->GetCellData()->SetScalars(cellScalars(block, good));
    scene.Mapper->SetScalarModeToUseCellData();
    Image cellRef[2];
    for (int o = 0; o < 2; ++o)
    {
      int status;
      cellRef[o] = render(valid, orders[o], status);
      std::cout << "== cell-scalar reference (44 valid cells), " << OrderName(orders[o]) << ": "
                << CheckImage(cellRef[o]).Str()
                << " witness=" << scene.Mapper->GetWitnessViolations() << "\n";
      ck.Check(status == 1 && !scene.Observer->GetWarning() && !scene.Observer->GetError() &&
          CheckImage(cellRef[o]).Covered > 1000,
        "cell-scalar reference renders without warnings");
    }
    badCase("NaN/Inf cell scalars on 4 of 48 cells", full, cellRef, "with NaN/Inf scalars", 44, 4);
    scene.Mapper->SetScalarModeToDefault();
  }

  // ---- 4. NaN / Inf point coordinates.
  {
    MeshBuilder m = block;
    const double bad[3] = { NaN, Inf, -Inf };
    for (int k = 0; k < 3; ++k)
    {
      double p[4][3];
      LooseTetPoints(p, 0.05 * k);
      p[k + 1][k] = bad[k];
      const double sv[4] = { 0.4, 1.0, 0.9, 1.2 };
      m.AddLooseTet(p, sv);
    }
    badCase("NaN/+Inf/-Inf point coordinates (3 loose tets)", m.Grid(), ref,
      "with NaN/Inf points", 48, 3);
  }

  // ---- 5. Degenerate tetrahedra.
  {
    MeshBuilder m = block;
    // Four coplanar points.
    vtkIdType a = m.AddPoint(0.2, 0.2, 0.5, 0.5), b = m.AddPoint(0.8, 0.3, 0.5, 1.0),
              c = m.AddPoint(0.3, 0.9, 0.5, 0.7), d = m.AddPoint(0.5, 0.5, 0.5, 1.1);
    m.AddCell(VTK_TETRA, { a, b, c, d });
    // A repeated point id.
    m.AddCell(VTK_TETRA, { a, b, c, a });
    // Distinct ids, two identical coordinates.
    vtkIdType e = m.AddPoint(0.2, 0.2, 0.5, 0.5), f = m.AddPoint(0.4, 0.4, 0.9, 0.3);
    m.AddCell(VTK_TETRA, { a, b, e, f });
    // Four collinear points.
    vtkIdType g0 = m.AddPoint(0.1, 0.1, 0.1, 0.1), g1 = m.AddPoint(0.3, 0.3, 0.3, 0.2),
              g2 = m.AddPoint(0.6, 0.6, 0.6, 0.3), g3 = m.AddPoint(0.9, 0.9, 0.9, 0.4);
    m.AddCell(VTK_TETRA, { g0, g1, g2, g3 });
    // Relative volume 1e-14 (below the documented 1e-12 threshold).
    vtkIdType h = m.AddPoint(0.5, 0.5, 0.5 + 1e-14, 0.2);
    m.AddCell(VTK_TETRA, { a, b, c, h });
    badCase("degenerate tets (coplanar, repeated id, repeated point, collinear, 6V/l^3~1e-14)",
      m.Grid(), ref, "degenerate", 48, 5);
  }

  // ---- 6. Inverted tetrahedra: all, and every other one.
  {
    const MeshBuilder inv = UnitBlock(2, true);
    // Check the builder really inverted them.
    int negative = 0;
    for (const auto& t : inv.Cells)
    {
      negative += inv.SignedVolume6(t) < 0;
    }
    std::cout << "== inverted block: " << negative << " of " << inv.Cells.size()
              << " tets have negative VTK orientation\n";
    ck.Check(negative == 48, "the inverted block has 48 negative tets");
    badCase("all 48 tets inverted", inv.Grid(), ref, "48 tetrahedra are inverted", 48, 0);
    MeshBuilder half = block;
    for (size_t i = 0; i < half.Cells.size(); i += 2)
    {
      std::swap(half.Cells[i][1], half.Cells[i][2]);
    }
    badCase("every other tet inverted", half.Grid(), ref, "24 tetrahedra are inverted", 48, 0);
  }

  // ---- 7. Empty grids.
  {
    std::cout << "== empty vtkUnstructuredGrid (no points, no cells, no arrays)\n";
    vtkNew<vtkUnstructuredGrid> empty;
    int status = -1;
    scene.Mapper->SetCellOrdering(orders[1]);
    scene.Mapper->SetInputData(empty);
    scene.Observer->Clear();
    Image img = Render(scene.Mapper, cam, scene.Volume, W, H, &status);
    Sanity s = CheckImage(img);
    std::cout << "  status=" << status << " " << s.Str() << " warning: '"
              << Msg(scene.Observer->GetWarningMessage()) << "' error: '"
              << Msg(scene.Observer->GetErrorMessage()) << "'\n";
    ck.Check(scene.Observer->GetWarning() || scene.Observer->GetError(), "empty grid: reported");
    ck.Check(img.W == W && img.H == H && s.Ok() && s.Covered == 0 && s.MaxRGB == 0,
      "empty grid: zero image of the requested size");

    std::cout << "== points and scalars but 0 cells\n";
    MeshBuilder m = block;
    m.Cells.clear();
    m.Types.clear();
    auto pointsOnly = m.Grid();
    for (int o = 0; o < 2; ++o)
    {
      img = render(pointsOnly, orders[o], status);
      s = CheckImage(img);
      std::cout << "  " << OrderName(orders[o]) << ": status=" << status << " " << s.Str()
                << " warning: '" << Msg(scene.Observer->GetWarningMessage()) << "' error: '"
                << Msg(scene.Observer->GetErrorMessage()) << "'\n";
      ck.Check(status == 1 && scene.Observer->GetWarning() && !scene.Observer->GetError(),
        "0 cells: a warning, no error, RenderImage returns 1");
      ck.Check(s.Ok() && s.Covered == 0 && s.MaxRGB == 0, "0 cells: zero image");
      ck.Check(scene.Mapper->GetNumberOfRenderedCells() == 0, "0 cells: 0 rendered");
    }
  }

  // ---- 8. Cell types the CPU path does not render, mixed with the tets, in
  // view (hexahedra, wedges, pyramids and quadratic cells are rendered: see
  // TestMixed*).
  {
    MeshBuilder m = block;
    auto P = [&](double x, double y, double z) { return m.AddPoint(x, y, z, DefaultField(x, y, z)); };
    vtkIdType hx[4] = { P(0.1, 0.1, 0.55), P(0.9, 0.1, 0.55), P(0.9, 0.9, 0.55), P(0.1, 0.9, 0.55) };
    // A Lagrange tetrahedron (10 nodes), a triangle and a vertex.
    std::vector<vtkIdType> qt;
    const double qv[4][3] = { { 0.2, 0.2, 0.3 }, { 0.8, 0.2, 0.3 }, { 0.2, 0.8, 0.3 },
      { 0.2, 0.2, 0.9 } };
    for (auto& v : qv)
    {
      qt.push_back(P(v[0], v[1], v[2]));
    }
    const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
    for (auto& e : edges)
    {
      qt.push_back(P(0.5 * (qv[e[0]][0] + qv[e[1]][0]), 0.5 * (qv[e[0]][1] + qv[e[1]][1]),
        0.5 * (qv[e[0]][2] + qv[e[1]][2])));
    }
    m.AddCell(VTK_LAGRANGE_TETRAHEDRON, qt);
    m.AddCell(VTK_TRIANGLE, { hx[0], hx[1], hx[2] });
    m.AddCell(VTK_VERTEX, { hx[3] });
    badCase("48 tets + Lagrange tetrahedron, triangle, vertex", m.Grid(), ref,
      "not yet supported by the CPU projection path", 48, 3);

    // A single hexahedron: rendered (general cells), no message.
    MeshBuilder h;
    auto Q = [&](double x, double y, double z) { return h.AddPoint(x, y, z, DefaultField(x, y, z)); };
    vtkIdType hh[8] = { Q(0, 0, 0), Q(1, 0, 0), Q(1, 1, 0), Q(0, 1, 0), Q(0, 0, 1), Q(1, 0, 1),
      Q(1, 1, 1), Q(0, 1, 1) };
    h.AddCell(VTK_HEXAHEDRON, std::vector<vtkIdType>(hh, hh + 8));
    auto hg = h.Grid();
    for (int o = 0; o < 2; ++o)
    {
      int status;
      const Image img = render(hg, orders[o], status);
      const Sanity s = CheckImage(img);
      std::cout << "== a single hexahedron, " << OrderName(orders[o]) << ": status=" << status
                << " " << s.Str() << " warning: '" << Msg(scene.Observer->GetWarningMessage())
                << "'\n";
      ck.Check(status == 1 && scene.NoMessages(), "hexahedron only: rendered, no message");
      ck.Check(s.Ok() && s.Covered > 1000, "hexahedron only: a sane image covering > 1000 pixels");
    }
  }

  // ---- Information: the class doc promises "one warning per render"; the
  // mapper warns when it (re)validates the input. Reported, not asserted.
  {
    MeshBuilder m = block;
    m.AddCell(VTK_VERTEX, { 0 });
    auto g = m.Grid();
    int status;
    render(g, orders[0], status);
    const bool first = scene.Observer->GetWarning();
    scene.Observer->Clear();
    Render(scene.Mapper, cam, scene.Volume, W, H, &status);
    std::cout << "== information: same bad grid rendered twice without Modified(): warning on "
              << "render 1: " << first << ", on render 2: " << scene.Observer->GetWarning()
              << " (class doc: 'skipped with one warning per render')\n";
  }

  // ---- 9. Everything at once, then the valid block again: no stale state.
  {
    int status;
    const Image again = render(blockGrid, orders[0], status);
    const DiffStats d = Diff(again, ref[0]);
    std::cout << "== the valid block after all bad inputs: " << d.Str() << "\n";
    ck.Check(
      status == 1 && !scene.Observer->GetWarning() && !scene.Observer->GetError() && d.Max == 0.0,
      "the valid block renders bit-identically after the bad inputs, without messages");
  }
  return ck.Result();
}
