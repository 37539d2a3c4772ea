/**
 * @file    vtkHighOrderTileGeometry.h
 * @brief   Private to vtkHighOrderProjectorTile: exact ray clipping against a
 *          cell's four face planes (scalar, and four planes at once in vector
 *          lanes) and the window-x span of a projected cell on a pixel row.
 *
 * Header only (inline helpers of one translation unit), in namespace
 * hovTileGeometry.
 * @sa vtkHighOrderProjectorTile
 */
#ifndef vtkHighOrderTileGeometry_h
#define vtkHighOrderTileGeometry_h

#include "vtkHighOrderProjectorTile.h" // CellRecord
#include "vtkHighOrderViewRays.h"      // Ray

#include <algorithm> // std::min, std::max
#include <cstring>   // memcpy into vector registers

namespace hovTileGeometry
{
using Ray = vtkHighOrderViewRays::Ray;
using CellRecord = vtkHighOrderProjectorTile::CellRecord;

/// Exact clip of a ray against the four face planes; false if it misses.
/// A ray parallel to a face and exactly in its plane (num == 0) is resolved
/// by the symbolic displacement e px + e^2 py of vtkHighOrderViewRays: inside
/// iff n.px < 0, or n.px == 0 and n.py < 0. The two cells sharing a face hold
/// opposite canonical normals, so exactly one of them takes such a ray.
inline bool ClipRay(const CellRecord& cell, const Ray& ray, double tMax, const glm::dvec3& px,
  const glm::dvec3& py, double& tIn, double& tOut)
{
  tIn = 0.0;
  tOut = tMax;
  for (int k = 0; k < 4; ++k)
  {
    const glm::dvec3 normal(cell.NX[k], cell.NY[k], cell.NZ[k]);
    const double denom = glm::dot(normal, ray.Direction);
    const double num = cell.Offset[k] - glm::dot(normal, ray.Origin);
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
      const double nx = glm::dot(normal, px);
      if (nx > 0.0 || (nx == 0.0 && glm::dot(normal, py) >= 0.0))
      {
        return false;
      }
    }
  }
  return tIn < tOut;
}

#if defined(__GNUC__) // GCC and Clang: vector extensions
#define HOV_CLIP_LANES 1
/// The four face planes of a cell, one per lane (a GCC/Clang vector: two SSE2
/// or one AVX instruction per operation).
typedef double V4 __attribute__((vector_size(4 * sizeof(double))));
struct FacePlanes
{
  V4 NX, NY, NZ, Offset;
  explicit FacePlanes(const CellRecord& cell)
  {
    std::memcpy(&this->NX, cell.NX, sizeof(V4));
    std::memcpy(&this->NY, cell.NY, sizeof(V4));
    std::memcpy(&this->NZ, cell.NZ, sizeof(V4));
    std::memcpy(&this->Offset, cell.Offset, sizeof(V4));
  }
};

/**
 * ClipRay() for the four planes at once, branch free: the same products,
 * sums and quotients in the same order (dot products as glm::dot computes
 * them), and min/max, which do not depend on the order, so the result is
 * bit-identical. Returns -1 (undecided: call ClipRay) if a ray is parallel to
 * a face (denominator exactly 0), where ClipRay's tie rules apply.
 */
inline int ClipRayLanes(const FacePlanes& f, const Ray& ray, double tMax, double& tIn, double& tOut)
{
  const V4 denom = (f.NX * ray.Direction.x + f.NY * ray.Direction.y) + f.NZ * ray.Direction.z;
  const V4 num = f.Offset - ((f.NX * ray.Origin.x + f.NY * ray.Origin.y) + f.NZ * ray.Origin.z);
  if (denom[0] == 0.0 || denom[1] == 0.0 || denom[2] == 0.0 || denom[3] == 0.0)
  {
    return -1;
  }
  const V4 t = num / denom;
  const V4 zero = {};
  const V4 big = zero + 1e300 * 1e300; // +inf: no constraint
  const V4 enter = denom < zero ? t : -big;
  const V4 leave = denom > zero ? t : big;
  tIn = std::max(std::max(std::max(0.0, enter[0]), std::max(enter[1], enter[2])), enter[3]);
  tOut = std::min(std::min(std::min(tMax, leave[0]), std::min(leave[1], leave[2])), leave[3]);
  return tIn < tOut ? 1 : 0;
}
#endif

/**
 * The six projected edges of a cell, set up once per cell for RowSpan():
 * the projection is the convex hull of the projected vertices, and a row
 * meets a convex hull of points in the span of its crossings with all
 * segments between them.
 */
struct ProjectedEdges
{
  double PX[6], PY[6], QY[6], DX[6], InvDY[6];
  explicit ProjectedEdges(const CellRecord& cell)
  {
    int e = 0;
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
      }
    }
  }
};

/// Window-x range of the projected cell on the row at height y; false if
/// the row misses it. (Round-off here only widens or narrows the candidate
/// pixels by far less than BoxMargin; the ray clip decides exactly.)
inline bool RowSpan(const ProjectedEdges& edges, double y, double& xMin, double& xMax)
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
}

#endif
