// hovStein::View keeps the depth ranges and screen extents of every cell only
// for the merge (Setup(..., true)); for the adjacency graph (false) only those
// of the cells cut by the near plane, by clip index, and no clip index at all
// when no point is behind it. Both give the same status, visible points,
// depth range and extents of every cell they keep: a random tetrahedral block
// seen from outside (perspective and parallel: nothing clipped) and a holed
// block seen from inside its hole (cells cut), each view set up in a fresh View
// and in one View reused across all of them (no stale entries).
#include "hovSortMeshes.h"
#include "hovSteinGeometry.h"
#include "hovSteinView.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

using namespace hovTest;

namespace
{
/// Every cell's status, clip index, visible points and depth range the same
/// in @p a (per-cell extents) and @p b; extents equal where @p b keeps them.
/// Returns the number of cells cut by the near plane.
vtkIdType Compare(Checker& ck, const hovStein::Geometry& g, const hovStein::View& a,
  const hovStein::View& b, const std::string& what)
{
  vtkIdType cut = 0, same = 0, extents = 0;
  double pa[3 * 64], pb[3 * 64];
  for (vtkIdType c = 0; c < g.NumberOfCells; ++c)
  {
    bool ok = a.Status[c] == b.Status[c] && a.Clip(c) == b.Clip(c);
    const int na = a.VisiblePoints(g, c, pa), nb = b.VisiblePoints(g, c, pb);
    ok = ok && na == nb && std::equal(pa, pa + 3 * na, pb);
    double fa, ra, fb, rb;
    a.DepthRange(g, c, fa, ra);
    b.DepthRange(g, c, fb, rb);
    ok = ok && fa == fb && ra == rb;
    if (b.Clip(c) >= 0)
    {
      ++cut;
      extents += a.FrontOf(c) == b.FrontOf(c) && a.RearOf(c) == b.RearOf(c) &&
        std::equal(a.BoxOf(c), a.BoxOf(c) + 4, b.BoxOf(c)) &&
        b.Status[c] == hovStein::StatusStraddle;
    }
    same += ok;
  }
  ck.Check(same == g.NumberOfCells,
    what + ": status, clip index, visible points and depth range of every cell as with extents (" +
      std::to_string(same) + " of " + std::to_string(g.NumberOfCells) + ")");
  ck.Check(extents == cut,
    what + ": the cut cells' depth ranges and extents as with extents (" + std::to_string(extents) +
      " of " + std::to_string(cut) + ")");
  ck.Check(static_cast<vtkIdType>(b.Front.size()) == cut &&
      static_cast<vtkIdType>(b.Rear.size()) == cut &&
      static_cast<vtkIdType>(b.Box.size()) == 4 * cut,
    what + ": without extents, one entry per cut cell");
  ck.Check(b.ClipIndex.empty() ==
      std::all_of(b.Valid.begin(), b.Valid.end(), [](std::uint8_t v) { return v != 0; }),
    what + ": a clip index exactly when some point is behind the near plane");
  return cut;
}
} // namespace

int TestSteinViewExtents(int, char*[])
{
  Checker ck;
  struct Case
  {
    std::string Name;
    vtkSmartPointer<vtkUnstructuredGrid> Grid;
    SortView View;
    bool Cut; ///< cells cut by the near plane expected
  };
  std::vector<Case> cases;
  vtkSmartPointer<vtkUnstructuredGrid> block = RandomTetMesh(6, 5);
  double b[6];
  block->GetBounds(b);
  const std::vector<SortView> outside = RandomViews(b, 2, 31); // perspective, parallel
  cases.push_back({ "block, " + outside[0].Name, block, outside[0], false });
  cases.push_back({ "block, " + outside[1].Name, block, outside[1], false });
  vtkSmartPointer<vtkUnstructuredGrid> holed = HoledBlock(5, 22);
  holed->GetBounds(b);
  const double eye[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), b[4] + 0.3 * (b[5] - b[4]) };
  const double focal[3] = { b[0], b[2], b[5] };
  cases.push_back({ "holed, inside the hole", holed, InsideView("inside", eye, focal), true });
  cases.push_back({ "block again, " + outside[0].Name, block, outside[0], false });

  hovStein::View reused; // set up for every case in turn
  for (const Case& k : cases)
  {
    hovStein::Geometry g;
    g.Build(k.Grid, nullptr);
    vtkNew<vtkCamera> cam;
    k.View.Apply(cam);
    hovStein::View all, fresh;
    all.Setup(g, cam, true);
    fresh.Setup(g, cam, false);
    reused.Setup(g, cam, false);
    const vtkIdType cut = Compare(ck, g, all, fresh, k.Name + " (fresh)");
    Compare(ck, g, all, reused, k.Name + " (reused)");
    ck.Check(k.Cut ? cut > 0 : cut == 0 && fresh.ClipIndex.empty(),
      k.Name + ": " + std::to_string(cut) + " cells cut by the near plane" +
        (k.Cut ? " (some expected)" : " (none expected, no clip index)"));
  }
  return ck.Result();
}
