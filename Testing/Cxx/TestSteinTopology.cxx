// The face adjacency of vtkSteinVisibilitySort (hovStein::Topology,
// Filters/hovSteinTopology.h) against an independent count from VTK's own
// cell faces: on conforming meshes of correctly oriented cells (Kuhn
// tetrahedra, jittered hexahedra, the mixed mesh, a block with holes) every
// face that two cells share is an interior face with those two cells, and
// every face of one cell only is a boundary face; the per-cell lists agree
// with the interior faces. With a duplicated cell (three cells on some faces,
// two on the same side of others) those faces are boundary faces. And the
// 32-bit face entries give exactly the arrays of the 64-bit ones
// (Topology::Build's wideEntries), so the wide path, used only beyond 4G
// points or 512M cells, is exercised (also where a triangle's and a
// quadrilateral's keys agree on three ids: overlapping cells).
// ParallelBuckets (the counting sort of the set-up) gives a serial stable
// counting sort's buckets for 0 to 300001 items (1 to 4 blocks) and 997 or
// 200003 keys under 1 to 4 threads and the Sequential backend.
#include "hovSortMeshes.h"
#include "hovSteinBuckets.h"
#include "hovSteinTopology.h"
#include "hovTestScenes.h"

#include "vtkCell.h"
#include "vtkGenericCell.h"
#include "vtkCellType.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

using namespace hovTest;

namespace
{
using Key = std::array<vtkIdType, 4>;

/// Sorted point ids of a face (-1 padding a triangle at the end).
Key SortedKey(const vtkIdType* ids, int n)
{
  Key k = { -1, -1, -1, -1 };
  std::copy(ids, ids + n, k.begin());
  std::sort(k.begin(), k.begin() + n);
  return k;
}

/// Per face key, the cells that have it (VTK's cell faces).
std::map<Key, std::vector<vtkIdType>> ReferenceFaces(vtkUnstructuredGrid* grid)
{
  std::map<Key, std::vector<vtkIdType>> faces;
  ForEachVTKFace(grid, [&](vtkIdType c, const std::vector<vtkIdType>& ids) {
    faces[SortedKey(ids.data(), static_cast<int>(ids.size()))].push_back(c);
  });
  return faces;
}

/// The key of face f of cell c in our geometry.
Key OurKey(const hovStein::Geometry& g, vtkIdType c, int f)
{
  vtkIdType ids[4];
  const int n = g.OrientedFace(c, f, ids);
  return SortedKey(ids, n);
}

bool SameArrays(const hovStein::Topology& a, const hovStein::Topology& b)
{
  bool same = a.A == b.A && a.B == b.B && a.FaceA == b.FaceA && a.TripleA == b.TripleA &&
    a.CellFaceOffsets == b.CellFaceOffsets && a.CellFaces == b.CellFaces &&
    a.CellNeighbours == b.CellNeighbours && a.BoundaryFaces == b.BoundaryFaces &&
    a.NumberOfBoundaryCells == b.NumberOfBoundaryCells && a.Boundary.size() == b.Boundary.size();
  for (size_t i = 0; same && i < a.Boundary.size(); ++i)
  {
    same = a.Boundary[i].Cell == b.Boundary[i].Cell && a.Boundary[i].Face == b.Boundary[i].Face &&
      a.Boundary[i].Mode == b.Boundary[i].Mode;
  }
  return same;
}

/**
 * Builds the topology of @p grid (32- and 64-bit entries) and checks it.
 * @p conforming: every shared face must be interior. @p duplicate: the last
 * cell is a copy of cell @p duplicate, whose faces must all be boundary faces.
 */
void Run(Checker& ck, const std::string& name, vtkUnstructuredGrid* grid, bool conforming,
  vtkIdType duplicate = -1)
{
  hovStein::Geometry g;
  g.Build(grid, nullptr);
  hovStein::Topology narrow, wide;
  narrow.Build(g);
  wide.Build(g, true);
  const std::map<Key, std::vector<vtkIdType>> reference = ReferenceFaces(grid);

  // The interior faces: keys and cells against the reference.
  std::set<std::pair<Key, std::pair<vtkIdType, vtkIdType>>> ours, expected;
  long badFace = 0;
  for (vtkIdType i = 0; i < narrow.NumberOfInteriorFaces(); ++i)
  {
    const vtkIdType a = narrow.A[i], b = narrow.B[i];
    const Key k = OurKey(g, a, narrow.FaceA[i]);
    ours.insert({ k, { std::min(a, b), std::max(a, b) } });
    // B has the same face (some face of B with this key).
    bool found = false;
    for (int f = 0; f < hovStein::GetShape(g.Kinds[b]).NumFaces; ++f)
    {
      found = found || OurKey(g, b, f) == k;
    }
    badFace += !found;
  }
  long shared = 0, single = 0;
  for (const auto& entry : reference)
  {
    const std::vector<vtkIdType>& cells = entry.second;
    shared += cells.size() == 2;
    single += cells.size() == 1;
    if (cells.size() == 2)
    {
      expected.insert(
        { entry.first, { std::min(cells[0], cells[1]), std::max(cells[0], cells[1]) } });
    }
  }
  long boundaryBits = 0;
  for (std::uint8_t bits : narrow.BoundaryFaces)
  {
    for (; bits; bits &= bits - 1)
    {
      ++boundaryBits;
    }
  }
  // The per-cell lists: each interior face once in A's list and once in B's.
  long listErrors = 0;
  for (vtkIdType c = 0; c < g.NumberOfCells; ++c)
  {
    for (vtkIdType e = narrow.CellFaceOffsets[c]; e < narrow.CellFaceOffsets[c + 1]; ++e)
    {
      const vtkIdType i = narrow.CellFaces[e] / 2;
      const bool isB = narrow.CellFaces[e] % 2 == 1;
      listErrors += (isB ? narrow.B[i] : narrow.A[i]) != c;
      listErrors += (isB ? narrow.A[i] : narrow.B[i]) != narrow.CellNeighbours[e];
    }
  }
  const long listed = static_cast<long>(narrow.CellFaceOffsets[g.NumberOfCells]);
  std::cout << "  " << name << ": cells " << g.NumberOfCells << ", interior "
            << narrow.NumberOfInteriorFaces() << " (faces of two cells " << shared
            << "), boundary faces " << boundaryBits << " (faces of one cell " << single
            << "), boundary cells " << narrow.NumberOfBoundaryCells << "\n";
  ck.Check(narrow.NumberOfInteriorFaces() > 0, name + ": interior faces found");
  ck.Check(badFace == 0, name + ": each interior face is a face of both its cells");
  ck.Check(listErrors == 0 && listed == 2 * narrow.NumberOfInteriorFaces(),
    name + ": per-cell lists hold each interior face on both sides");
  ck.Check(static_cast<size_t>(boundaryBits) == narrow.Boundary.size(),
    name + ": boundary list = boundary bits");
  ck.Check(
    SameArrays(narrow, wide), name + ": 32-bit and 64-bit face entries give the same topology");
  if (conforming)
  {
    ck.Check(ours == expected, name + ": interior faces = the faces two cells share (VTK's faces)");
    ck.Check(boundaryBits == single, name + ": boundary faces = the faces of one cell");
  }
  if (duplicate >= 0)
  {
    const vtkIdType copy = g.NumberOfCells - 1;
    const int numFaces = hovStein::GetShape(g.Kinds[copy]).NumFaces;
    const std::uint8_t all = static_cast<std::uint8_t>((1 << numFaces) - 1);
    ck.Check(narrow.BoundaryFaces[copy] == all && narrow.BoundaryFaces[duplicate] == all,
      name + ": every face of the duplicated cell and of its copy is a boundary face");
    // Everything else as without the copy: the faces two cells share, less
    // those of the duplicated cell.
    long expectedInterior = 0;
    for (const auto& p : expected)
    {
      expectedInterior += p.second.first != duplicate && p.second.second != copy;
    }
    ck.Check(narrow.NumberOfInteriorFaces() == expectedInterior,
      name + ": the other shared faces stay interior");
  }
}

/// ParallelBuckets against a serial stable counting sort on @p numItems
/// random items (0 to 3 keys each, some keys never used) under several
/// thread counts.
void CheckBuckets(Checker& ck, vtkIdType numItems, vtkIdType numKeys)
{
  std::mt19937 rng(17);
  std::vector<std::vector<vtkIdType>> keys(numItems);
  for (auto& k : keys)
  {
    const int m = static_cast<int>(rng() % 4);
    for (int i = 0; i < m; ++i)
    {
      k.push_back(static_cast<vtkIdType>(rng() % (numKeys - 7)));
    }
  }
  std::vector<std::vector<vtkIdType>> expected(numKeys);
  for (vtkIdType item = 0; item < numItems; ++item)
  {
    for (vtkIdType k : keys[item])
    {
      expected[k].push_back(3 * item + 1);
    }
  }
  auto items = [&keys](vtkIdType begin, vtkIdType end, auto&& emit) {
    for (vtkIdType item = begin; item < end; ++item)
    {
      for (vtkIdType k : keys[item])
      {
        emit(k, [item]() { return 3 * item + 1; });
      }
    }
  };
  struct Setting
  {
    int Threads;
    std::string Backend;
  };
  for (const Setting& setting : std::vector<Setting>{ { 1, "TBB" }, { 2, "TBB" }, { 3, "TBB" },
         { 4, "TBB" }, { 1, "Sequential" } })
  {
    std::vector<vtkIdType> start;
    hovStein::FillBuffer<vtkIdType> out;
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ setting.Threads, setting.Backend, false },
      [&]() { hovStein::ParallelBuckets(numItems, numKeys, items, start, out); });
    bool same = static_cast<vtkIdType>(start.size()) == numKeys + 1 && start[0] == 0;
    for (vtkIdType k = 0; same && k < numKeys; ++k)
    {
      same = std::vector<vtkIdType>(out.begin() + start[k], out.begin() + start[k + 1]) ==
        expected[k];
    }
    ck.Check(same,
      "ParallelBuckets, " + std::to_string(numItems) + " items, " + std::to_string(numKeys) +
        " keys, " + setting.Backend + " " +
        std::to_string(setting.Threads) + " thread(s): a serial stable counting sort's buckets");
  }
}

/**
 * Overlapping cells (not a valid mesh): two pyramids sharing their square
 * base (0, 1, 2, 3) and two tetrahedra sharing the triangle (0, 1, 2) in the
 * same plane, on opposite sides each. Both shared faces are interior, and
 * their sorted keys agree on their first three ids: the triangle's padding
 * must sort the same way with 32-bit and 64-bit face entries.
 */
vtkSmartPointer<vtkUnstructuredGrid> TriangleInQuad()
{
  vtkNew<vtkPoints> points;
  const double xyz[6][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
    { 0.5, 0.5, 1 }, { 0.5, 0.5, -1 } };
  for (const auto& p : xyz)
  {
    points->InsertNextPoint(p);
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  const vtkIdType up[5] = { 0, 1, 2, 3, 4 }, down[5] = { 0, 3, 2, 1, 5 };
  const vtkIdType tetUp[4] = { 0, 1, 2, 4 }, tetDown[4] = { 0, 2, 1, 5 };
  grid->InsertNextCell(VTK_TETRA, 4, tetUp);
  grid->InsertNextCell(VTK_PYRAMID, 5, up);
  grid->InsertNextCell(VTK_TETRA, 4, tetDown);
  grid->InsertNextCell(VTK_PYRAMID, 5, down);
  return grid;
}

/// @p grid with a copy of cell @p c appended.
vtkSmartPointer<vtkUnstructuredGrid> WithCopy(vtkUnstructuredGrid* grid, vtkIdType c)
{
  vtkNew<vtkUnstructuredGrid> out;
  out->DeepCopy(grid);
  vtkNew<vtkIdList> ids;
  grid->GetCellPoints(c, ids);
  out->InsertNextCell(grid->GetCellType(c), ids);
  return out;
}
}

int TestSteinTopology(int, char*[])
{
  Checker ck;
  for (vtkIdType numItems : { 0, 1, 3, 20011 }) // 1, 3, 2 or 4 blocks
  {
    CheckBuckets(ck, numItems, 997);
  }
  CheckBuckets(ck, 300001, 200003); // the passes over keys in chunks

  const double o[3] = { -1.25, 0.5, 3.0 }, size[3] = { 2.0, 1.5, 0.75 };
  vtkSmartPointer<vtkUnstructuredGrid> tets = JitteredTetBlock(5, 4, 3, o, size, 0.3, 7).Grid();
  Run(ck, "jittered Kuhn tetrahedra", tets, true);
  Run(ck, "jittered hexahedra", JitteredHexBlock(4, 0.2), true);
  Run(ck, "mixed mesh", MixedMesh(3), true);
  Run(ck, "block with holes", HoledBlock(6, 5), true);
  // An interior cell (a middle one) and a copy of it: its faces are shared by
  // three cells, or by two on the same side.
  const vtkIdType middle = tets->GetNumberOfCells() / 2;
  Run(ck, "tetrahedra with a duplicated cell", WithCopy(tets, middle), false, middle);
  Run(ck, "a triangle inside a quadrilateral (overlapping cells)", TriangleInQuad(), false);
  return ck.Result();
}
