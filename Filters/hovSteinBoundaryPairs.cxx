// Boundary face pairs of vtkSteinVisibilitySort's ADJACENCY_GRAPH (see hovSteinBoundaryPairs.h).
#include "hovSteinBoundaryPairs.h"

#include "hovSteinObstructs.h" // Obstruction
#include "hovSteinRounding.h"  // FloatDown, FloatUp

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace hovStein
{
namespace
{
/// Per-view data of one face: screen extents, depth range, corners.
struct FaceData
{
  float Box[4]; ///< xmin, xmax, ymin, ymax (outward)
  double Front, Rear;
  vtkIdType Ids[4];     ///< corners (point ids)
  vtkIdType Triple[3];  ///< exact plane (outward counterclockwise) if Exact
  std::uint8_t NumIds;
  std::uint8_t Exact;   ///< 1: Triple spans the exact face plane
};

void FillFaceData(const Geometry& g, const View& v, const ViewFace& vf, FaceData& d)
{
  const vtkIdType c = vf.Cell;
  d.NumIds = static_cast<std::uint8_t>(g.OrientedFace(c, vf.Face, d.Ids));
  d.Exact = (g.FaceCode(c, vf.Face) & 3) == FaceExact && vf.Roles != 3;
  if (d.Exact)
  {
    g.ExactTriple(c, vf.Face, d.Triple);
  }
  if (v.Status[c] != StatusVisible)
  {
    std::copy(v.Box.data() + 4 * c, v.Box.data() + 4 * c + 4, d.Box);
    d.Front = v.Front[c];
    d.Rear = v.Rear[c];
    return;
  }
  double box[4] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  d.Front = VTK_DOUBLE_MAX;
  d.Rear = -VTK_DOUBLE_MAX;
  for (int i = 0; i < d.NumIds; ++i)
  {
    const double* p = v.Proj.data() + 3 * d.Ids[i];
    box[0] = std::min(box[0], p[0]);
    box[1] = std::max(box[1], p[0]);
    box[2] = std::min(box[2], p[1]);
    box[3] = std::max(box[3], p[1]);
    d.Front = std::min(d.Front, p[2]);
    d.Rear = std::max(d.Rear, p[2]);
  }
  d.Box[0] = FloatDown(box[0]);
  d.Box[1] = FloatUp(box[1]);
  d.Box[2] = FloatDown(box[2]);
  d.Box[3] = FloatUp(box[3]);
}

/**
 * Some corner of @p other lies on the outer side of the plane of the exact face
 * @p d, or within a margin inside it (true if @p d is not exact). The margin,
 * 1e-9 times the coordinate magnitude (100x the rounding tolerance of
 * Obstructs()), keeps nearly coplanar non-conforming interfaces whose points
 * are not exactly coplanar (sheared sliding interfaces) among the candidates.
 */
bool SomeCornerOutside(const Geometry& g, const FaceData& d, const FaceData& other)
{
  if (!d.Exact)
  {
    return true;
  }
  const double *a = g.Point(d.Triple[0]), *b = g.Point(d.Triple[1]), *c = g.Point(d.Triple[2]);
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double w[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double n[3] = { u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0] };
  const double scale = g.Diagonal + std::max({ std::abs(a[0]), std::abs(a[1]), std::abs(a[2]) });
  const double margin = 1e-9 * scale * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int i = 0; i < other.NumIds; ++i)
  {
    const double* p = g.Point(other.Ids[i]);
    if (n[0] * (p[0] - a[0]) + n[1] * (p[1] - a[1]) + n[2] * (p[2] - a[2]) >= -margin)
    {
      return true;
    }
  }
  return false;
}

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

/// Tiles about the mean extent of the faces, within the view window, at most ~4 per face.
PairGrid MakePairGrid(const View& v, const std::vector<FaceData>& data)
{
  double r[4] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (const FaceData& d : data)
  {
    r[0] = std::min(r[0], double(d.Box[0]));
    r[1] = std::max(r[1], double(d.Box[1]));
    r[2] = std::min(r[2], double(d.Box[2]));
    r[3] = std::max(r[3], double(d.Box[3]));
  }
  const double* win = v.Frame.Window;
  PairGrid grid;
  grid.X0 = std::max(r[0], win[0]);
  grid.Y0 = std::max(r[2], win[2]);
  const double width = std::min(r[1], win[1]) - grid.X0, height = std::min(r[3], win[3]) - grid.Y0;
  double w = 0, h = 0;
  for (const FaceData& d : data)
  {
    w += std::min(double(d.Box[1]) - d.Box[0], width);
    h += std::min(double(d.Box[3]) - d.Box[2], height);
  }
  const double count = std::max<double>(1, static_cast<double>(data.size()));
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

/// A face in the ENTRY lists of the tiles: what the pair search rejects on,
/// stored contiguously in tile order (the search streams through it).
struct EntryRecord
{
  float Box[4];
  double Rear;
  vtkIdType Cell;
  vtkIdType Face; ///< index into the faces
};

/// The tiles a face's extents cover: ix0, ix1, iy0, iy1 (inclusive).
using TileRange = std::array<int, 4>;

/// Tile lists (CSR) of the faces with role @p role (1 EXIT, 2 ENTRY);
/// @p lists holds the face indices, in face order within each tile.
void BinFaces(const PairGrid& grid, const std::vector<ViewFace>& faces,
  const std::vector<TileRange>& ranges, int role, std::vector<vtkIdType>& start,
  std::vector<vtkIdType>& lists)
{
  const vtkIdType nt = static_cast<vtkIdType>(grid.NX) * grid.NY;
  start.assign(nt + 1, 0);
  auto forTiles = [&](const TileRange& r, auto&& fn) {
    for (int iy = r[2]; iy <= r[3]; ++iy)
    {
      for (int ix = r[0]; ix <= r[1]; ++ix)
      {
        fn(static_cast<vtkIdType>(iy) * grid.NX + ix);
      }
    }
  };
  const vtkIdType nf = static_cast<vtkIdType>(faces.size());
  for (vtkIdType i = 0; i < nf; ++i)
  {
    if (faces[i].Roles & role)
    {
      forTiles(ranges[i], [&](vtkIdType tile) { ++start[tile + 1]; });
    }
  }
  for (vtkIdType i = 0; i < nt; ++i)
  {
    start[i + 1] += start[i];
  }
  lists.resize(start[nt]);
  std::vector<vtkIdType> cursor(start.begin(), start.end() - 1);
  for (vtkIdType i = 0; i < nf; ++i)
  {
    if (faces[i].Roles & role)
    {
      forTiles(ranges[i], [&](vtkIdType tile) { lists[cursor[tile]++] = i; });
    }
  }
}
}

void BoundaryEdges(const Geometry& g, const View& v, const std::vector<ViewFace>& faces,
  std::vector<std::pair<vtkIdType, vtkIdType>>& edges, PairStats& stats)
{
  const vtkIdType nf = static_cast<vtkIdType>(faces.size());
  if (nf < 2)
  {
    return;
  }
  std::vector<FaceData> data(nf);
  vtkSMPTools::For(0, nf, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      FillFaceData(g, v, faces[i], data[i]);
    }
  });

  const PairGrid grid = MakePairGrid(v, data);
  // Per tile, the EXIT faces against the ENTRY faces: two lists, the entries
  // as contiguous records (the search rejects almost every candidate on them).
  std::vector<TileRange> ranges(nf);
  vtkSMPTools::For(0, nf, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      const float* b = data[i].Box;
      ranges[i] = { grid.IX(b[0]), grid.IX(b[1]), grid.IY(b[2]), grid.IY(b[3]) };
    }
  });
  std::vector<vtkIdType> exitStart, exitLists, entryStart, entryLists;
  BinFaces(grid, faces, ranges, 1, exitStart, exitLists);
  BinFaces(grid, faces, ranges, 2, entryStart, entryLists);
  std::vector<EntryRecord> entries(entryLists.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(entryLists.size()), 4096,
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const vtkIdType gi = entryLists[i];
        EntryRecord& e = entries[i];
        std::copy(data[gi].Box, data[gi].Box + 4, e.Box);
        e.Rear = data[gi].Rear;
        e.Cell = faces[gi].Cell;
        e.Face = gi;
      }
    });

  const vtkIdType nt = static_cast<vtkIdType>(grid.NX) * grid.NY;
  const vtkIdType numBlocks = std::min<vtkIdType>(nt, 256);
  std::vector<std::vector<std::pair<vtkIdType, vtkIdType>>> blockPairs(numBlocks);
  std::vector<vtkIdType> blockCount(numBlocks, 0);
  vtkSMPTools::For(0, numBlocks, 1, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType blk = b0; blk < b1; ++blk)
    {
      for (vtkIdType tile = blk * nt / numBlocks; tile < (blk + 1) * nt / numBlocks; ++tile)
      {
        const int ix = static_cast<int>(tile % grid.NX), iy = static_cast<int>(tile / grid.NX);
        const EntryRecord* first = entries.data() + entryStart[tile];
        const EntryRecord* last = entries.data() + entryStart[tile + 1];
        for (vtkIdType i = exitStart[tile]; i < exitStart[tile + 1]; ++i)
        {
          const vtkIdType fi = exitLists[i];
          const FaceData& F = data[fi];
          const vtkIdType a = faces[fi].Cell;
          const double front = F.Front - 1e-9 * (std::abs(F.Front) + g.Diagonal);
          for (const EntryRecord* G = first; G != last; ++G)
          {
            if (G->Cell == a || G->Rear < front || Disjoint(F.Box, G->Box) ||
              grid.IX(std::max(F.Box[0], G->Box[0])) != ix ||
              grid.IY(std::max(F.Box[2], G->Box[2])) != iy)
            {
              continue;
            }
            ++blockCount[blk];
            if (SomeCornerOutside(g, F, data[G->Face]) && SomeCornerOutside(g, data[G->Face], F))
            {
              blockPairs[blk].emplace_back(a, G->Cell);
            }
          }
        }
      }
    }
  });

  std::vector<std::pair<vtkIdType, vtkIdType>> pairs;
  for (vtkIdType blk = 0; blk < numBlocks; ++blk)
  {
    stats.FacePairs += blockCount[blk];
    pairs.insert(pairs.end(), blockPairs[blk].begin(), blockPairs[blk].end());
  }
  vtkSMPTools::Sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  const vtkIdType np = static_cast<vtkIdType>(pairs.size());

  stats.Tests += np;
  std::vector<std::uint8_t> hit(np, 0);
  vtkSMPThreadLocal<std::shared_ptr<Obstruction>> local;
  vtkSMPTools::For(0, np, 64, [&](vtkIdType begin, vtkIdType end) {
    std::shared_ptr<Obstruction>& ob = local.Local();
    if (!ob)
    {
      ob.reset(new Obstruction(g, v));
    }
    for (vtkIdType i = begin; i < end; ++i)
    {
      hit[i] = ob->Obstructs(pairs[i].first, pairs[i].second);
    }
  });

  for (vtkIdType i = 0; i < np; ++i)
  {
    if (hit[i])
    {
      edges.emplace_back(pairs[i].second, pairs[i].first);
    }
  }
}
}
