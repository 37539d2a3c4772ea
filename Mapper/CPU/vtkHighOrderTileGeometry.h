/**
 * @file    vtkHighOrderTileGeometry.h
 * @brief   Private to vtkHighOrderProjectorTile: exact ray clipping against a
 *          cell's four face planes (scalar, and four pixels at once in vector
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

/// Exact clip of a ray against four face planes, normalOf(k) . x <= offset[k];
/// false if it misses. A ray parallel to a face and exactly in its plane
/// (num == 0) is resolved by the symbolic displacement e px + e^2 py of
/// vtkHighOrderViewRays: inside iff n.px < 0, or n.px == 0 and n.py < 0. The
/// two cells sharing a face hold opposite canonical normals, so exactly one of
/// them takes such a ray.
template <typename NormalOf>
inline bool ClipRayFaces(NormalOf&& normalOf, const double* offset, const Ray& ray, double tMax,
  const glm::dvec3& px, const glm::dvec3& py, double& tIn, double& tOut)
{
  tIn = 0.0;
  tOut = tMax;
  for (int k = 0; k < 4; ++k)
  {
    const glm::dvec3 normal = normalOf(k);
    const double denom = glm::dot(normal, ray.Direction);
    const double num = offset[k] - glm::dot(normal, ray.Origin);
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

/// ClipRayFaces() on a cell record's planes.
inline bool ClipRay(const CellRecord& cell, const Ray& ray, double tMax, const glm::dvec3& px,
  const glm::dvec3& py, double& tIn, double& tOut)
{
  return ClipRayFaces(
    [&](int k) { return glm::dvec3(cell.NX[k], cell.NY[k], cell.NZ[k]); }, cell.Offset, ray,
    tMax, px, py, tIn, tOut);
}

#if defined(__GNUC__) // GCC and Clang: vector extensions
#define HOV_CLIP_LANES 1
/// Four doubles in a GCC/Clang vector: one AVX instruction, or two SSE2 ones.
typedef double V4 __attribute__((vector_size(4 * sizeof(double))));

using TileRays = vtkHighOrderProjectorTile::TileRays;
constexpr int PixelLanes = 4; ///< pixels per ClipPixelLanes() call

/**
 * ClipRay() and the scalars at both ends of the segment for the PixelLanes
 * consecutive pixels from @p p, one pixel per lane, branch free: the same
 * products, sums and quotients in the same order (dot products as glm::dot
 * computes them), and min/max, which do not depend on the order, so the
 * result is bit-identical. hit[l]: 1 hit, 0 miss, -1 undecided (a ray
 * parallel to a face, denominator exactly 0, where ClipRay's tie rules apply).
 */
__attribute__((always_inline)) inline void ClipPixelLanes(const CellRecord& cell, const TileRays& r, size_t p, double* tIn,
  double* tOut, double* sIn, double* sOut, signed char* hit)
{
  V4 ox, oy, oz, dx, dy, dz, tMax;
  std::memcpy(&ox, r.OX + p, sizeof(V4));
  std::memcpy(&oy, r.OY + p, sizeof(V4));
  std::memcpy(&oz, r.OZ + p, sizeof(V4));
  std::memcpy(&dx, r.DX + p, sizeof(V4));
  std::memcpy(&dy, r.DY + p, sizeof(V4));
  std::memcpy(&dz, r.DZ + p, sizeof(V4));
  std::memcpy(&tMax, r.TMax + p, sizeof(V4));
  const V4 zero = {};
  const V4 big = zero + 1e300 * 1e300; // +inf: no constraint
  V4 enter[4], leave[4];
  auto parallel = zero < zero; // no lane yet
  for (int k = 0; k < 4; ++k)
  {
    const double nx = cell.NX[k], ny = cell.NY[k], nz = cell.NZ[k];
    const V4 denom = (nx * dx + ny * dy) + nz * dz;
    const V4 num = cell.Offset[k] - ((nx * ox + ny * oy) + nz * oz);
    parallel |= denom == zero;
    const V4 t = num / denom;
    enter[k] = denom < zero ? t : -big;
    leave[k] = denom > zero ? t : big;
  }
  // std::max(a, b) is a < b ? b : a, std::min(a, b) is b < a ? b : a, per lane.
  const V4 in0 = zero < enter[0] ? enter[0] : zero;
  const V4 in12 = enter[1] < enter[2] ? enter[2] : enter[1];
  const V4 in012 = in0 < in12 ? in12 : in0;
  const V4 vIn = in012 < enter[3] ? enter[3] : in012;
  const V4 out0 = leave[0] < tMax ? leave[0] : tMax;
  const V4 out12 = leave[2] < leave[1] ? leave[2] : leave[1];
  const V4 out012 = out12 < out0 ? out12 : out0;
  const V4 vOut = leave[3] < out012 ? leave[3] : out012;
  const glm::dvec3& g = cell.Gradient;
  const glm::dvec3& q = cell.RefPoint;
  const V4 sAtOrigin = cell.RefScalar + ((g.x * (ox - q.x) + g.y * (oy - q.y)) + g.z * (oz - q.z));
  const V4 slope = (g.x * dx + g.y * dy) + g.z * dz;
  const V4 vsIn = sAtOrigin + vIn * slope;
  const V4 vsOut = sAtOrigin + vOut * slope;
  std::memcpy(tIn, &vIn, sizeof(V4));
  std::memcpy(tOut, &vOut, sizeof(V4));
  std::memcpy(sIn, &vsIn, sizeof(V4));
  std::memcpy(sOut, &vsOut, sizeof(V4));
  const auto inside = vIn < vOut;
  for (int l = 0; l < PixelLanes; ++l)
  {
    hit[l] = static_cast<signed char>(parallel[l] ? -1 : (inside[l] ? 1 : 0));
  }
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
