// Visibility DAG of vtkSteinVisibilitySort's ADJACENCY_GRAPH algorithm (see hovSteinGraph.h).
#include "hovSteinGraph.h"

#include "hovGeometricPredicates.h" // exact Orient3d, Orient3dDirection
#include "hovSteinMerge.h"          // RadixSortDescending
#include "hovSteinObstructs.h"      // Obstruction

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

namespace hovStein
{
namespace
{
enum Side : std::int8_t
{
  EyeOutside = -1, ///< the eye strictly on the outer side of the face plane
  EyeOn = 0,
  EyeInside = 1,
  EyeUndecided = 2 ///< non-planar face with the eye near it, or degenerate face
};

inline double Dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/**
 * Side of the eye for a Newell face. The corners lie within the slab of
 * half-width dev around the plane; a warped face's local normals may tilt by
 * about dev/h (h its shortest edge). Decide only when the eye is off the slab
 * by more than that tilt over the eye's distance, with a factor of 2 to spare.
 */
int NewellSide(const Geometry& g, const ViewFrame& f, vtkIdType c, int face)
{
  const Plane& p = g.FacePlane(c, face);
  const Shape& s = GetShape(g.Kinds[c]);
  const vtkIdType* ids = g.CellCorners(c);
  double h = VTK_DOUBLE_MAX, centre[3] = { 0, 0, 0 };
  for (int i = 0; i < s.FaceSize[face]; ++i)
  {
    const double* a = g.Point(ids[s.Faces[face][i]]);
    const double* b = g.Point(ids[s.Faces[face][(i + 1) % s.FaceSize[face]]]);
    const double e[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    h = std::min(h, std::sqrt(Dot(e, e)));
    for (int k = 0; k < 3; ++k)
    {
      centre[k] += a[k] / s.FaceSize[face];
    }
  }
  if (!(h > 0))
  {
    return EyeUndecided;
  }
  const double tilt = 4 * p.Deviation / h;
  double value, margin;
  if (f.Parallel)
  {
    value = -Dot(p.N, f.Dop);
    margin = tilt;
  }
  else
  {
    const double r[3] = { centre[0] - f.Eye[0], centre[1] - f.Eye[1], centre[2] - f.Eye[2] };
    value = Dot(p.N, f.Eye) + p.D;
    margin = 2 * p.Deviation + tilt * std::sqrt(Dot(r, r));
  }
  return value > margin ? EyeOutside : (value < -margin ? EyeInside : EyeUndecided);
}

/// Side of the eye with respect to face @p face of cell @p c (see Side).
int EyeSide(const Geometry& g, const ViewFrame& f, vtkIdType c, int face)
{
  const int mode = g.FaceCode(c, face) & 3;
  if (mode == FaceExact)
  {
    vtkIdType t[3];
    g.ExactTriple(c, face, t);
    const double back[3] = { -f.Dop[0], -f.Dop[1], -f.Dop[2] };
    const double *a = g.Point(t[0]), *b = g.Point(t[1]), *cc = g.Point(t[2]);
    return f.Parallel ? hov::Orient3dDirection(a, b, cc, back) : hov::Orient3d(a, b, cc, f.Eye);
  }
  return mode == FaceNewell ? NewellSide(g, f, c, face) : EyeUndecided;
}

inline bool Ordered(const View& v, vtkIdType c)
{
  return v.Status[c] == StatusVisible || v.Status[c] == StatusStraddle;
}

/// Per interior face: +1 edge A -> B, -1 edge B -> A, 0 none, 2 undecided.
void FaceDirections(const Geometry& g, const Topology& t, const View& v, std::vector<std::int8_t>& dir)
{
  const vtkIdType m = t.NumberOfInteriorFaces();
  dir.resize(m);
  vtkSMPTools::For(0, m, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      if (!Ordered(v, t.A[i]) || !Ordered(v, t.B[i]))
      {
        dir[i] = 0;
        continue;
      }
      const int side = EyeSide(g, v.Frame, t.A[i], t.FaceA[i]);
      // Eye on B's side (outside A's face): B is nearer, A comes first.
      dir[i] = static_cast<std::int8_t>(side == EyeOutside ? 1 : side == EyeInside ? -1 : side == EyeOn ? 0 : 2);
    }
  });
}

/// Per cell: bit 0 EXIT, bit 1 ENTRY (see hovSteinGraph.h).
void Roles(const Geometry& g, const Topology& t, const View& v, const std::vector<std::int8_t>& dir,
  std::vector<std::uint8_t>& roles)
{
  const vtkIdType n = g.NumberOfCells;
  roles.assign(n, 0);
  vtkSMPTools::For(0, n, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType c = begin; c < end; ++c)
    {
      const std::uint8_t faces = t.BoundaryFaces[c];
      if (!faces || !Ordered(v, c))
      {
        continue;
      }
      std::uint8_t r = 0;
      for (int f = 0; f < MaxFaces && r != 3; ++f)
      {
        if (faces & (1 << f))
        {
          const int side = EyeSide(g, v.Frame, c, f);
          r |= side == EyeInside ? 1 : side == EyeOutside ? 2 : side == EyeOn ? 0 : 3;
        }
      }
      roles[c] = r;
    }
  });
  for (size_t i = 0; i < dir.size(); ++i)
  {
    if (dir[i] == 2)
    {
      roles[t.A[i]] = roles[t.B[i]] = 3;
    }
  }
}
}

namespace
{
/// Uniform screen grid for the pair search.
struct PairGrid
{
  int NX = 1, NY = 1;
  double X0 = 0, Y0 = 0, DX = 1, DY = 1;
  int IX(double x) const
  {
    const double u = (x - this->X0) / this->DX;
    return u <= 0 ? 0 : (u >= this->NX - 1 ? this->NX - 1 : static_cast<int>(u));
  }
  int IY(double y) const
  {
    const double u = (y - this->Y0) / this->DY;
    return u <= 0 ? 0 : (u >= this->NY - 1 ? this->NY - 1 : static_cast<int>(u));
  }
};

/// Tiles about the mean extent of the cells, within the view window, at most ~4 per cell.
PairGrid MakePairGrid(const View& v, const std::vector<vtkIdType>& cells)
{
  double r[4] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  double w = 0, h = 0;
  for (vtkIdType c : cells)
  {
    const float* b = v.Box.data() + 4 * c;
    r[0] = std::min(r[0], double(b[0]));
    r[1] = std::max(r[1], double(b[1]));
    r[2] = std::min(r[2], double(b[2]));
    r[3] = std::max(r[3], double(b[3]));
  }
  const double* win = v.Frame.Window;
  PairGrid grid;
  grid.X0 = std::max(r[0], win[0]);
  grid.Y0 = std::max(r[2], win[2]);
  const double width = std::min(r[1], win[1]) - grid.X0, height = std::min(r[3], win[3]) - grid.Y0;
  for (vtkIdType c : cells)
  {
    const float* b = v.Box.data() + 4 * c;
    w += std::min(double(b[1]) - b[0], width);
    h += std::min(double(b[3]) - b[2], height);
  }
  const double count = std::max<double>(1, static_cast<double>(cells.size()));
  w /= count;
  h /= count;
  if (!(width > 0 && height > 0 && w > 0 && h > 0) || !std::isfinite(width * height))
  {
    return grid; // one tile
  }
  double nx = width / w, ny = height / h;
  const double scale = std::sqrt(std::min(1.0, 4 * count / (nx * ny)));
  nx = std::min(4096.0, std::max(1.0, std::floor(nx * scale)));
  ny = std::min(4096.0, std::max(1.0, std::floor(ny * scale)));
  grid.NX = static_cast<int>(nx);
  grid.NY = static_cast<int>(ny);
  grid.DX = width / grid.NX;
  grid.DY = height / grid.NY;
  return grid;
}

inline bool Disjoint(const float* a, const float* b)
{
  return a[1] <= b[0] || b[1] <= a[0] || a[3] <= b[2] || b[3] <= a[2];
}

/// Obstructs() edges (b, a) for EXIT a, ENTRY b with overlapping extents.
void ObstructEdges(const Geometry& g, const View& v, const std::vector<std::uint8_t>& roles,
  std::vector<std::pair<vtkIdType, vtkIdType>>& edges, GraphStats& stats)
{
  std::vector<vtkIdType> cells;
  for (vtkIdType c = 0; c < g.NumberOfCells; ++c)
  {
    if (roles[c])
    {
      cells.push_back(c);
      stats.ExitCells += roles[c] & 1;
      stats.EntryCells += (roles[c] >> 1) & 1;
    }
  }
  if (cells.size() < 2)
  {
    return;
  }
  const PairGrid grid = MakePairGrid(v, cells);
  const vtkIdType nt = static_cast<vtkIdType>(grid.NX) * grid.NY;
  std::vector<vtkIdType> start(nt + 1, 0);
  auto forTiles = [&](vtkIdType c, auto&& fn) {
    const float* b = v.Box.data() + 4 * c;
    for (int iy = grid.IY(b[2]), iy1 = grid.IY(b[3]); iy <= iy1; ++iy)
    {
      for (int ix = grid.IX(b[0]), ix1 = grid.IX(b[1]); ix <= ix1; ++ix)
      {
        fn(static_cast<vtkIdType>(iy) * grid.NX + ix);
      }
    }
  };
  for (vtkIdType c : cells)
  {
    forTiles(c, [&](vtkIdType tile) { ++start[tile + 1]; });
  }
  for (vtkIdType i = 0; i < nt; ++i)
  {
    start[i + 1] += start[i];
  }
  std::vector<vtkIdType> lists(start[nt]);
  {
    std::vector<vtkIdType> cursor(start.begin(), start.end() - 1);
    for (vtkIdType c : cells)
    {
      forTiles(c, [&](vtkIdType tile) { lists[cursor[tile]++] = c; });
    }
  }
  const vtkIdType numBlocks = std::min<vtkIdType>(nt, 256);
  std::vector<std::vector<std::pair<vtkIdType, vtkIdType>>> blockEdges(numBlocks);
  std::vector<vtkIdType> blockTests(numBlocks, 0);
  vtkSMPThreadLocal<std::shared_ptr<Obstruction>> local;
  vtkSMPTools::For(0, numBlocks, 1, [&](vtkIdType b0, vtkIdType b1) {
    std::shared_ptr<Obstruction>& ob = local.Local();
    if (!ob)
    {
      ob.reset(new Obstruction(g, v));
    }
    for (vtkIdType blk = b0; blk < b1; ++blk)
    {
      for (vtkIdType tile = blk * nt / numBlocks; tile < (blk + 1) * nt / numBlocks; ++tile)
      {
        const int ix = static_cast<int>(tile % grid.NX), iy = static_cast<int>(tile / grid.NX);
        for (vtkIdType i = start[tile]; i < start[tile + 1]; ++i)
        {
          const vtkIdType a = lists[i];
          if (!(roles[a] & 1))
          {
            continue;
          }
          const float* ba = v.Box.data() + 4 * a;
          for (vtkIdType j = start[tile]; j < start[tile + 1]; ++j)
          {
            const vtkIdType b = lists[j];
            const float* bb = v.Box.data() + 4 * b;
            if (b == a || !(roles[b] & 2) || Disjoint(ba, bb) ||
              grid.IX(std::max(ba[0], bb[0])) != ix || grid.IY(std::max(ba[2], bb[2])) != iy)
            {
              continue;
            }
            ++blockTests[blk];
            if (ob->Obstructs(a, b))
            {
              blockEdges[blk].emplace_back(b, a);
            }
          }
        }
      }
    }
  });
  for (vtkIdType blk = 0; blk < numBlocks; ++blk)
  {
    stats.Tests += blockTests[blk];
    edges.insert(edges.end(), blockEdges[blk].begin(), blockEdges[blk].end());
  }
}

/// Compressed adjacency of the face edges and the Obstructs() edges.
void BuildDigraph(const Topology& t, const std::vector<std::int8_t>& dir,
  const std::vector<std::pair<vtkIdType, vtkIdType>>& extra, vtkIdType n, Digraph& d)
{
  d.Offsets.assign(n + 1, 0);
  const vtkIdType m = t.NumberOfInteriorFaces();
  for (vtkIdType i = 0; i < m; ++i)
  {
    if (dir[i] == 1 || dir[i] == -1)
    {
      ++d.Offsets[(dir[i] == 1 ? t.A[i] : t.B[i]) + 1];
    }
  }
  for (const auto& e : extra)
  {
    ++d.Offsets[e.first + 1];
  }
  for (vtkIdType c = 0; c < n; ++c)
  {
    d.Offsets[c + 1] += d.Offsets[c];
  }
  d.Targets.resize(d.Offsets[n]);
  std::vector<vtkIdType> cursor(d.Offsets.begin(), d.Offsets.end() - 1);
  for (vtkIdType i = 0; i < m; ++i)
  {
    if (dir[i] == 1)
    {
      d.Targets[cursor[t.A[i]]++] = t.B[i];
    }
    else if (dir[i] == -1)
    {
      d.Targets[cursor[t.B[i]]++] = t.A[i];
    }
  }
  for (const auto& e : extra)
  {
    d.Targets[cursor[e.first]++] = e.second;
  }
}

/// Cells split into ordered ones (by id) and the others (back to front by rearmost depth).
void SplitCells(const View& v, vtkIdType n, std::vector<vtkIdType>& first, std::vector<vtkIdType>& rough)
{
  for (vtkIdType c = 0; c < n; ++c)
  {
    (Ordered(v, c) ? rough : first).push_back(c);
  }
  std::vector<float> keys(first.size());
  for (size_t i = 0; i < first.size(); ++i)
  {
    keys[i] = static_cast<float>(v.Rear[first[i]]);
  }
  RadixSortDescending(first, keys);
}
}

void SortByGraph(const Geometry& g, const Topology& t, const View& v,
  std::vector<vtkIdType>& order, GraphStats& stats)
{
  const vtkIdType n = g.NumberOfCells;
  stats = GraphStats();
  order.clear();
  order.reserve(n);
  std::vector<vtkIdType> first, rough;
  SplitCells(v, n, first, rough);
  order.insert(order.end(), first.begin(), first.end());
  if (rough.empty())
  {
    return;
  }
  std::vector<std::int8_t> dir;
  FaceDirections(g, t, v, dir);
  std::vector<std::uint8_t> roles;
  Roles(g, t, v, dir, roles);
  std::vector<std::pair<vtkIdType, vtkIdType>> extra;
  ObstructEdges(g, v, roles, extra, stats);
  for (std::int8_t s : dir)
  {
    stats.FaceEdges += s == 1 || s == -1;
    stats.Undecided += s == 2;
  }
  stats.ObstructEdges = static_cast<vtkIdType>(extra.size());
  Digraph d;
  BuildDigraph(t, dir, extra, n, d);
  TopologicalOrder(d, rough, v.Rear, order, stats);
}
}
