// Covering sheets of vtkSteinVisibilitySort's boundary pair search (see hovSteinSheets.h).
#include "hovSteinSheets.h"

#include "hovGeometricPredicates.h" // exact Orient2d
#include "hovSteinBuckets.h"         // ParallelBuckets
#include "hovSteinRounding.h"       // FloatDown, FloatUp

#include "vtkSMPTools.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>

namespace hovStein
{
void BoundaryAdjacency::Build(const Geometry& g, const Topology& t)
{
  const vtkIdType nb = static_cast<vtkIdType>(t.Boundary.size());
  this->Generation = t.Generation;
  if (nb >= INT32_MAX)
  {
    this->Across.clear(); // (no sheets: ViewFace::Boundary is -1 beyond INT32_MAX)
    return;
  }
  this->Across.resize(4 * nb); // every entry is written below, in parallel
  if (nb == 0)
  {
    return;
  }
  // Corners of every boundary face (a triangle's fourth -1), then the
  // boundary faces of every point.
  FillBuffer<vtkIdType> corners(4 * nb);
  FillBuffer<std::uint8_t> sizes(nb);
  vtkSMPTools::For(0, nb, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType k = begin; k < end; ++k)
    {
      vtkIdType* ids = corners.data() + 4 * k;
      const int n = g.OrientedFace(t.Boundary[k].Cell, t.Boundary[k].Face, ids);
      std::fill(ids + n, ids + 4, -1);
      sizes[k] = static_cast<std::uint8_t>(n);
    }
  });
  const vtkIdType numPoints = static_cast<vtkIdType>(g.Points.size() / 3);
  std::vector<vtkIdType> start;
  FillBuffer<std::int32_t> facesOf;
  auto items = [&](vtkIdType begin, vtkIdType end, auto&& emit) {
    for (vtkIdType k = begin; k < end; ++k)
    {
      for (int i = 0; i < sizes[k]; ++i)
      {
        emit(corners[4 * k + i], [k]() { return static_cast<std::int32_t>(k); });
      }
    }
  };
  ParallelBuckets(nb, numPoints, items, start, facesOf);
  // Across edge (p, q) of face k: the one other boundary face with p and q,
  // if it runs that edge the other way, q to p (consistently oriented: the
  // two faces then lie on opposite sides of the edge when both face the eye).
  vtkSMPTools::For(0, nb, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType k = begin; k < end; ++k)
    {
      const int n = sizes[k];
      for (int e = 0; e < n; ++e)
      {
        const vtkIdType p = corners[4 * k + e], q = corners[4 * k + (e + 1) % n];
        std::int32_t other = -1;
        int count = 0;
        for (vtkIdType s = start[p]; s < start[p + 1]; ++s)
        {
          const std::int32_t j = facesOf[s];
          if (j == k)
          {
            continue;
          }
          const vtkIdType* cj = corners.data() + 4 * static_cast<vtkIdType>(j);
          const int nj = sizes[j];
          const int at = static_cast<int>(std::find(cj, cj + nj, q) - cj);
          if (at < nj)
          {
            ++count;
            other = cj[(at + 1) % nj] == p ? j : -2; // -2: the same way round
          }
        }
        this->Across[4 * k + e] = count == 1 && other >= 0 ? other : -1;
      }
      std::fill(this->Across.data() + 4 * k + n, this->Across.data() + 4 * k + 4, -1);
    }
  });
}

namespace
{
/// The point @p c strictly inside the projected triangle @p d (exact; d.Screen).
bool StrictlyInside(const FaceData& d, const double c[2])
{
  const double(*p)[2] = d.Corners;
  const int s0 = hov::Orient2d(p[0], p[1], c), s1 = hov::Orient2d(p[1], p[2], c);
  const int s2 = hov::Orient2d(p[2], p[0], c);
  return s0 != 0 && s0 == s1 && s1 == s2;
}

/// Union-find root with path halving.
int Root(std::vector<int>& parent, int a)
{
  while (parent[a] != a)
  {
    parent[a] = parent[parent[a]];
    a = parent[a];
  }
  return a;
}
}

void SheetCover::Cover(const FillBuffer<FaceData>& data, const PairGrid& grid,
  const vtkIdType* entryStart, const TileRecord* entryRecords)
{
  const vtkIdType nt = grid.NumberOfTiles();
  const vtkIdType numBlocks = std::min<vtkIdType>(nt, 256);
  const double spanX = grid.DX * grid.NX, spanY = grid.DY * grid.NY;
  std::vector<std::vector<std::pair<double, double>>> blockCovers(numBlocks);
  std::vector<SheetStats> blockStats(numBlocks);
  this->CoverStart.assign(nt + 1, 0);
  vtkSMPTools::For(0, numBlocks, 1, [&](vtkIdType b0, vtkIdType b1) {
    std::vector<vtkIdType> members; // sheet faces (face indices), increasing
    std::vector<int> parent;
    std::vector<char> blocked, inside;
    std::vector<double> front, rear;
    for (vtkIdType blk = b0; blk < b1; ++blk)
    {
      std::vector<std::pair<double, double>>& covers = blockCovers[blk];
      for (vtkIdType tile = blk * nt / numBlocks; tile < (blk + 1) * nt / numBlocks; ++tile)
      {
        const int ix = static_cast<int>(tile % grid.NX), iy = static_cast<int>(tile / grid.NX);
        const double centre[2] = { grid.X0 + (ix + 0.5) * grid.DX, grid.Y0 + (iy + 0.5) * grid.DY };
        if (grid.IX(centre[0]) != ix || grid.IY(centre[1]) != iy)
        {
          continue; // (a degenerate grid)
        }
        // The sheets' faces whose extents meet the tile (the lists are in
        // increasing face order), joined through their shared edges into the
        // tile's local sheets; their data fetched meanwhile.
        members.clear();
        for (vtkIdType s = entryStart[tile]; s < entryStart[tile + 1]; ++s)
        {
          const vtkIdType i = entryRecords[s].Face;
          if (this->Border[i] & SheetFace)
          {
            members.push_back(i);
            Prefetch(data.data() + i);
            Prefetch(reinterpret_cast<const char*>(data.data() + i) + 64);
            Prefetch(this->Across.data() + 3 * i);
          }
        }
        // (Build() runs before the records are sorted by depth: face order.)
        assert(std::is_sorted(members.begin(), members.end()));
        const int m = static_cast<int>(members.size());
        if (m == 0)
        {
          continue;
        }
        parent.resize(m);
        for (int a = 0; a < m; ++a)
        {
          parent[a] = a;
        }
        for (int a = 0; a < m; ++a)
        {
          for (int e = 0; e < 3; ++e)
          {
            const std::int32_t j = this->Across[3 * members[a] + e];
            if (j <= members[a]) // (-1, or joined from j's side: the relation is symmetric)
            {
              continue;
            }
            const auto it = std::lower_bound(members.begin() + a + 1, members.end(), j);
            if (it != members.end() && *it == j)
            {
              const int x = Root(parent, a);
              const int y = Root(parent, static_cast<int>(it - members.begin()));
              parent[std::max(x, y)] = std::min(x, y);
            }
          }
        }
        // A local sheet with a border edge in the tile is blocked; the others
        // cover the tile if its centre lies in one of their faces.
        blocked.assign(m, 0);
        inside.assign(m, 0);
        front.assign(m, VTK_DOUBLE_MAX);
        rear.assign(m, -VTK_DOUBLE_MAX);
        for (int a = 0; a < m; ++a)
        {
          const int r = Root(parent, a);
          const FaceData& d = data[members[a]];
          front[r] = std::min(front[r], d.Front);
          rear[r] = std::max(rear[r], d.Rear);
          const std::uint8_t border = this->Border[members[a]];
          for (int e = 0; e < 3 && !blocked[r]; ++e)
          {
            if (!(border & (1 << e)))
            {
              continue;
            }
            // The edge's extents, widened against the rounding of the
            // projection (1e-9 of the coordinates and the grid's span).
            const double* p = d.Corners[e];
            const double* q = d.Corners[(e + 1) % 3];
            const double x0 = std::min(p[0], q[0]), x1 = std::max(p[0], q[0]);
            const double y0 = std::min(p[1], q[1]), y1 = std::max(p[1], q[1]);
            const double mx = 1e-9 * (std::max(std::abs(x0), std::abs(x1)) + spanX);
            const double my = 1e-9 * (std::max(std::abs(y0), std::abs(y1)) + spanY);
            blocked[r] = grid.IX(FloatDown(x0 - mx)) <= ix && ix <= grid.IX(FloatUp(x1 + mx)) &&
              grid.IY(FloatDown(y0 - my)) <= iy && iy <= grid.IY(FloatUp(y1 + my));
          }
          // (Outside the face's extents, rounded outwards: not inside.)
          if (!inside[r] && d.Box[0] <= centre[0] && centre[0] <= d.Box[1] &&
            d.Box[2] <= centre[1] && centre[1] <= d.Box[3])
          {
            inside[r] = StrictlyInside(d, centre);
          }
        }
        const size_t before = covers.size();
        for (int a = 0; a < m; ++a)
        {
          if (parent[a] == a)
          {
            ++blockStats[blk].Sheets;
            if (!blocked[a] && inside[a])
            {
              covers.emplace_back(front[a], rear[a]);
            }
          }
        }
        // By decreasing front depth, each rear replaced by the least rear so
        // far (NearestRear() reads one prefix).
        const auto tileCovers = covers.begin() + static_cast<std::ptrdiff_t>(before);
        std::sort(tileCovers, covers.end(), std::greater<std::pair<double, double>>());
        for (auto c = tileCovers; c != covers.end(); ++c)
        {
          c->second = c == tileCovers ? c->second : std::min(c->second, (c - 1)->second);
        }
        this->CoverStart[tile + 1] = static_cast<vtkIdType>(covers.size() - before);
      }
    }
  });
  for (vtkIdType tile = 0; tile < nt; ++tile)
  {
    this->Stats.CoveredTiles += this->CoverStart[tile + 1] > 0;
    this->CoverStart[tile + 1] += this->CoverStart[tile];
  }
  this->Covers.clear();
  this->Covers.reserve(this->CoverStart[nt]);
  for (vtkIdType blk = 0; blk < numBlocks; ++blk)
  {
    this->Covers.insert(this->Covers.end(), blockCovers[blk].begin(), blockCovers[blk].end());
    this->Stats.Sheets += blockStats[blk].Sheets;
  }
  this->Stats.Covers = static_cast<vtkIdType>(this->Covers.size());
}

void SheetCover::Build(const Geometry& g, const Topology& t, const View& v,
  const BoundaryAdjacency& adjacency, const std::vector<ViewFace>& faces,
  const FillBuffer<FaceData>& data, const PairGrid& grid, const vtkIdType* entryStart,
  const TileRecord* entryRecords)
{
  this->Stats = SheetStats();
  this->NX = grid.NX;
  const vtkIdType nb = static_cast<vtkIdType>(t.Boundary.size());
  // The sheets' faces: ENTRY only (not undecided), of visible cells,
  // triangles with exact planes, counterclockwise on the screen as seen from
  // outside (exactly, in the projected points the tests use: joined faces
  // then lie on opposite sides of their shared edge there too).
  const ViewFrame& f = v.Frame;
  const double rxu[3] = { f.Right[1] * f.Up[2] - f.Right[2] * f.Up[1],
    f.Right[2] * f.Up[0] - f.Right[0] * f.Up[2], f.Right[0] * f.Up[1] - f.Right[1] * f.Up[0] };
  const int facing = rxu[0] * f.Dop[0] + rxu[1] * f.Dop[1] + rxu[2] * f.Dop[2] < 0 ? 1 : -1;
  this->FaceOf.assign(nb, -1);
  if (adjacency.Across.size() != 4 * static_cast<size_t>(nb))
  {
    // No adjacency (too many boundary faces): no sheets, no covers.
    this->CoverStart.assign(grid.NumberOfTiles() + 1, 0);
    this->Covers.clear();
    return;
  }
  const vtkIdType nf = static_cast<vtkIdType>(faces.size());
  vtkSMPTools::For(0, nf, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      const ViewFace& vf = faces[i];
      const FaceData& d = data[i];
      if (vf.Boundary < 0 || vf.Roles != 2 || !d.Screen || d.NumIds != 3 || t.Boundary[vf.Boundary].Cell != vf.Cell ||
        t.Boundary[vf.Boundary].Face != vf.Face || t.Boundary[vf.Boundary].Mode != FaceExact)
      {
        continue;
      }
      if (hov::Orient2d(d.Corners[0], d.Corners[1], d.Corners[2]) == facing)
      {
        this->FaceOf[vf.Boundary] = static_cast<std::int32_t>(i);
      }
    }
  });
  // Per face: sheet face or not, its neighbours across its edges (faces of
  // sheets), border edges (not shared with exactly one other sheet face).
  this->Border.resize(nf);
  this->Across.resize(3 * nf);
  vtkSMPTools::For(0, nf, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      const std::int32_t k = faces[i].Boundary;
      std::uint8_t border = 0;
      for (int e = 0; e < 3; ++e)
      {
        this->Across[3 * i + e] = -1;
      }
      if (k >= 0 && this->FaceOf[k] == i)
      {
        border = SheetFace;
        for (int e = 0; e < 3; ++e)
        {
          const std::int32_t j = adjacency.Across[4 * static_cast<vtkIdType>(k) + e];
          const std::int32_t other = j < 0 ? -1 : this->FaceOf[j];
          this->Across[3 * i + e] = other;
          border |= other < 0 ? (1 << e) : 0;
        }
      }
      this->Border[i] = border;
    }
  });
  this->Cover(data, grid, entryStart, entryRecords);
}

double SheetCover::NearestRear(vtkIdType tile, double after) const
{
  double rear = VTK_DOUBLE_MAX;
  for (vtkIdType c = this->CoverStart[tile]; c < this->CoverStart[tile + 1]; ++c)
  {
    if (!(this->Covers[c].first > after))
    {
      break;
    }
    rear = this->Covers[c].second;
  }
  return rear;
}

bool SheetCover::Separates(int ix0, int ix1, int iy0, int iy1, double after, double before) const
{
  for (int iy = iy0; iy <= iy1; ++iy)
  {
    for (int ix = ix0; ix <= ix1; ++ix)
    {
      if (!(this->NearestRear(static_cast<vtkIdType>(iy) * this->NX + ix, after) < before))
      {
        return false;
      }
    }
  }
  return true;
}

bool SheetCover::SeparatesBefore(
  int ix0, int ix1, int iy0, int iy1, int ix, int iy, double after, double before) const
{
  return (iy == iy0 || this->Separates(ix0, ix1, iy0, iy - 1, after, before)) &&
    (ix == ix0 || this->Separates(ix0, ix - 1, iy, iy, after, before));
}
}
