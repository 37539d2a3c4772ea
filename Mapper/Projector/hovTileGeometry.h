/**
 * @file    hovTileGeometry.h
 * @brief   Private to hov::ProjectorTile: exact ray clipping against a
 *          cell's four face planes and the window-x span of a projected cell
 *          on a pixel row (the pixel lanes: hovProjectorTileLanes.h).
 *
 * Header only (inline helpers of one translation unit), in namespace
 * hovTileGeometry.
 * @sa hov::ProjectorTile
 */
#ifndef hovTileGeometry_h
#define hovTileGeometry_h

#include "hovProjectorTile.h" // CellRecord
#include "hovViewRays.h"      // Ray

#include "hovRayClip.h" // ClipFourPlanes

#include <algorithm> // std::min, std::max

namespace hov::tile
{
using Ray = hov::ViewRays::Ray;
using CellRecord = hov::ProjectorTile::CellRecord;

/// Exact clip of a ray against four face planes, (nx, ny, nz)[k] . x <= offset[k];
/// false if it misses: hov::ClipFourPlanes (the pixel lanes' code, one ray).
/// A ray parallel to a face is decided plane by plane: outside the plane, a
/// miss; exactly in its plane (num == 0), by the symbolic displacement
/// e px + e^2 py of hov::ViewRays: inside iff n.px < 0, or n.px == 0 and
/// n.py < 0. The two cells sharing a face hold opposite canonical normals, so
/// exactly one of them takes such a ray.
inline bool ClipRayFaces(const double* nx, const double* ny, const double* nz,
  const double* offset, const Ray& ray, double tMax, const glm::dvec3& px, const glm::dvec3& py,
  double& tIn, double& tOut)
{
  const glm::dvec3& o = ray.Origin;
  const glm::dvec3& d = ray.Direction;
  bool parallel = false;
  ClipFourPlanes(nx, ny, nz, offset, o.x, o.y, o.z, d.x, d.y, d.z, tMax, tIn, tOut, parallel);
  if (!parallel)
  {
    return tIn < tOut;
  }
  tIn = 0.0;
  tOut = tMax;
  for (int k = 0; k < 4; ++k)
  {
    const glm::dvec3 normal(nx[k], ny[k], nz[k]);
    const double denom = glm::dot(normal, d);
    const double num = offset[k] - glm::dot(normal, o);
    if (denom > 0.0)
    {
      tOut = std::min(tOut, num / denom);
    }
    else if (denom < 0.0)
    {
      tIn = std::max(tIn, num / denom);
    }
    else if (num < 0.0)
    {
      return false;
    }
    else if (num == 0.0)
    {
      const double nPx = glm::dot(normal, px);
      if (nPx > 0.0 || (nPx == 0.0 && glm::dot(normal, py) >= 0.0))
      {
        return false;
      }
    }
  }
  return tIn < tOut;
}

/// ClipRayFaces() on a cell record's planes.
inline bool ClipRay(const CellRecord& cell, const Ray& ray, double tMax, const glm::dvec3& px,
  const glm::dvec3& py, double& tIn, double& tOut)
{
  return ClipRayFaces(cell.NX, cell.NY, cell.NZ, cell.Offset, ray, tMax, px, py, tIn, tOut);
}

/// True if the ray is parallel to a face (a zero denominator, as the lanes
/// compute it): ClipRay()'s tie rules decide.
inline bool IsUndecided(const CellRecord& cell, const Ray& ray)
{
  bool parallel = false;
  for (int k = 0; k < 4; ++k)
  {
    const double denom =
      (cell.NX[k] * ray.Direction.x + cell.NY[k] * ray.Direction.y) + cell.NZ[k] * ray.Direction.z;
    parallel = parallel || denom == 0.0;
  }
  return parallel;
}

/**
 * The six projected edges of a cell, set up once per cell for RowSpan():
 * the projection is the convex hull of the projected vertices, and a row
 * meets a convex hull of points in the span of its crossings with all
 * segments between them. A row strictly between two consecutive vertex
 * heights (band b between the sorted heights BandY[b] and BandY[b + 1])
 * crosses exactly the edges from a vertex below to a vertex above
 * (BandEdges[b], 3 or 4 of them), so RowSpan() computes only those.
 */
struct ProjectedEdges
{
  double PX[6], PY[6], QY[6], DX[6], InvDY[6];
  double BandY[4];
  int BandEdges[3][4]; ///< 3 or 4 edges (a third one repeated)
  explicit ProjectedEdges(const CellRecord& cell)
  {
    int e = 0;
    int edgeOf[4][4];
    for (int a = 0; a < 4; ++a)
    {
      for (int b = a + 1; b < 4; ++b, ++e)
      {
        const glm::dvec2& p = cell.Vertex[a];
        const glm::dvec2& q = cell.Vertex[b];
        this->PX[e] = p.x;
        this->PY[e] = p.y;
        this->QY[e] = q.y;
        this->DX[e] = q.x - p.x;
        this->InvDY[e] = p.y != q.y ? 1.0 / (q.y - p.y) : 0.0; // 0: a horizontal edge
        edgeOf[a][b] = edgeOf[b][a] = e;
      }
    }
    // Vertices by height (a sorting network of five branch-free compare and
    // exchanges: the order of equal heights does not matter), then the edges
    // of each band.
    int v[4] = { 0, 1, 2, 3 };
    double* y = this->BandY;
    for (int i = 0; i < 4; ++i)
    {
      y[i] = cell.Vertex[i].y;
    }
    auto exchange = [&](int a, int b) {
      const int swap = -static_cast<int>(y[b] < y[a]); // all bits set: swap
      const double ya = y[a], yb = y[b];
      y[a] = std::min(ya, yb);
      y[b] = std::max(ya, yb);
      const int va = v[a], vb = v[b];
      v[a] = (vb & swap) | (va & ~swap);
      v[b] = (va & swap) | (vb & ~swap);
    };
    exchange(0, 1);
    exchange(2, 3);
    exchange(0, 2);
    exchange(1, 3);
    exchange(1, 2);
    for (int b = 0; b < 3; ++b)
    {
      int count = 0;
      for (int lo = 0; lo <= b; ++lo)
      {
        for (int hi = b + 1; hi < 4; ++hi)
        {
          this->BandEdges[b][count++] = edgeOf[v[lo]][v[hi]];
        }
      }
      if (count == 3)
      {
        this->BandEdges[b][3] = this->BandEdges[b][0]; // min/max: a repeat changes nothing
      }
    }
  }
};

/// Distance, in cells of a tile's list, at which the per-cell data is
/// prefetched: cells come in visibility (or depth) order, scattered in memory,
/// and each one's few pixels take less time than a cache miss.
constexpr vtkIdType PrefetchDistance = 4;

/// Prefetch what the tile loop reads of ordered cell k.
inline void PrefetchCell(const hov::ProjectorTile::Frame& frame, vtkIdType k)
{
  const char* cell = reinterpret_cast<const char*>(&(*frame.Cells)[k]);
  for (size_t offset = 0; offset < sizeof(CellRecord); offset += 64)
  {
    __builtin_prefetch(cell + offset);
  }
}

/// std::ceil / std::floor to int for |v| < 2^30 (beyond: clamped to +-2^30),
/// without the library call's software rounding on baseline x86-64.
inline int CeilToInt(double v)
{
  v = std::min(std::max(v, -1073741824.0), 1073741824.0);
  const int i = static_cast<int>(v); // rounds toward zero
  return i + (static_cast<double>(i) < v ? 1 : 0);
}
inline int FloorToInt(double v)
{
  v = std::min(std::max(v, -1073741824.0), 1073741824.0);
  const int i = static_cast<int>(v);
  return i - (v < static_cast<double>(i) ? 1 : 0);
}

/// Window-x range of the projected cell on the row at height y; false if
/// the row misses it. (Round-off here only widens or narrows the candidate
/// pixels by far less than BoxMargin; the ray clip decides exactly.)
inline bool RowSpanAllEdges(const ProjectedEdges& edges, double y, double& xMin, double& xMax)
{
  xMin = 1e300;
  xMax = -1e300;
  for (int e = 0; e < 6; ++e)
  {
    if ((edges.PY[e] - y) * (edges.QY[e] - y) > 0.0)
    {
      continue; // the edge is entirely above or below the row
    }
    if (edges.InvDY[e] == 0.0)
    {
      xMin = std::min(xMin, std::min(edges.PX[e], edges.PX[e] + edges.DX[e]));
      xMax = std::max(xMax, std::max(edges.PX[e], edges.PX[e] + edges.DX[e]));
      continue;
    }
    const double x = edges.PX[e] + edges.DX[e] * ((y - edges.PY[e]) * edges.InvDY[e]);
    xMin = std::min(xMin, x);
    xMax = std::max(xMax, x);
  }
  return xMin <= xMax;
}

/// RowSpanAllEdges() by bands: a row strictly inside a band computes only
/// the band's edges (the others are entirely above or below it), the same
/// crossings in the same way; a row through a vertex takes all six.
inline bool RowSpan(const ProjectedEdges& edges, double y, double& xMin, double& xMax)
{
  if (y < edges.BandY[0] || edges.BandY[3] < y)
  {
    return false; // no edge reaches the row
  }
  const int b = (edges.BandY[1] < y) + (edges.BandY[2] < y);
  if (!(edges.BandY[b] < y && y < edges.BandY[b + 1]))
  {
    return RowSpanAllEdges(edges, y, xMin, xMax); // through a vertex
  }
  double x[4];
  for (int i = 0; i < 4; ++i)
  {
    const int e = edges.BandEdges[b][i];
    x[i] = edges.PX[e] + edges.DX[e] * ((y - edges.PY[e]) * edges.InvDY[e]);
  }
  xMin = std::min(std::min(x[0], x[1]), std::min(x[2], x[3]));
  xMax = std::max(std::max(x[0], x[1]), std::max(x[2], x[3]));
  return xMin <= xMax;
}
}

#endif
