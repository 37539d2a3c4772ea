// The pixel lanes of hov::ProjectorTile (declared in
// hovProjectorTileLanes.h): ray clipping of rows of pixels and row
// ranges of projected cells, several pixels or rows per vector instruction,
// and the compositing of the segment queue,
// with exactly the scalar code's operations, compiled for baseline x86-64
// and for AVX2 (chosen at load time; the same IEEE operations, no FMA).
#include "hovProjectorTileLanes.h"

#include "hovRayClip.h" // ClipFourPlanes, the lanes' clip

#include "hovCompositing.h" // CompositeBehind

#include <algorithm> // std::max
#include <cstring>   // memcpy into vector registers

namespace hov::tile
{
namespace
{
#if defined(__GNUC__) // GCC and Clang: vector extensions
/// Four doubles in a GCC/Clang vector: one AVX instruction (rows of pixels).
typedef double V4 __attribute__((vector_size(4 * sizeof(double))));
/// Two doubles: one SSE2 instruction (rows' short tails).
typedef double V2 __attribute__((vector_size(2 * sizeof(double))));

/**
 * ClipRay() and the scalars at both ends of the segment for the lanes of V
 * (consecutive pixels from @p p), one pixel per lane, branch free: the same
 * products, sums and quotients in the same order (dot products as glm::dot
 * computes them), and min/max, which do not depend on the order, so the
 * result is bit-identical. Writes lane l at index @p q + l of @p out; ANDs
 * into @p all, per lane, all bits set if the ray hits (not undecided), else 0.
 */
template <typename V, typename Mask>
__attribute__((always_inline)) inline void ClipPixelLanes(const CellRecord& cell,
  const TileRays& r, size_t p, const LaneOut& out, size_t q, const Mask& pastEnd, Mask& all)
{
  V ox, oy, oz, dx, dy, dz, tMax;
  std::memcpy(&ox, r.OX + p, sizeof(V));
  std::memcpy(&oy, r.OY + p, sizeof(V));
  std::memcpy(&oz, r.OZ + p, sizeof(V));
  std::memcpy(&dx, r.DX + p, sizeof(V));
  std::memcpy(&dy, r.DY + p, sizeof(V));
  std::memcpy(&dz, r.DZ + p, sizeof(V));
  std::memcpy(&tMax, r.TMax + p, sizeof(V));
  auto parallel = V{} < V{}; // no lane yet
  V vIn, vOut;
  ClipFourPlanes(cell.NX, cell.NY, cell.NZ, cell.Offset, ox, oy, oz, dx, dy, dz, tMax, vIn,
    vOut, parallel);
  const glm::dvec3& g = cell.Gradient;
  const glm::dvec3& c = cell.RefPoint;
  const V sAtOrigin = cell.RefScalar + ((g.x * (ox - c.x) + g.y * (oy - c.y)) + g.z * (oz - c.z));
  const V slope = (g.x * dx + g.y * dy) + g.z * dz;
  const V vsIn = sAtOrigin + vIn * slope;
  const V vsOut = sAtOrigin + vOut * slope;
  const V vLength = vOut - vIn;
  std::memcpy(out.TIn + q, &vIn, sizeof(V));
  std::memcpy(out.TOut + q, &vOut, sizeof(V));
  std::memcpy(out.SIn + q, &vsIn, sizeof(V));
  std::memcpy(out.SOut + q, &vsOut, sizeof(V));
  std::memcpy(out.Length + q, &vLength, sizeof(V));
  if (out.Pixel)
  {
    // Four ints per store (a V2 block writes two lanes more: the arrays are
    // padded, and the next block or span overwrites them).
    typedef int I4 __attribute__((vector_size(4 * sizeof(int))));
    const I4 pixel = I4{ 0, 1, 2, 3 } + static_cast<int>(p);
    const I4 interval = I4{} + cell.Interval;
    std::memcpy(out.Pixel + q, &pixel, sizeof(I4));
    std::memcpy(out.Interval + q, &interval, sizeof(I4));
  }
  all &= ((vIn < vOut) & ~parallel) | pastEnd;
}

/**
 * ClipPixelLanes() for the pixels [p, p + count) of a row, written at
 * [q, q + count) of @p out (up to PixelLanes - 1 lanes more are written: the
 * arrays are padded, as are the tile's rays). Blocks of four lanes, and of
 * two for a row's last one or two pixels. Returns true if every pixel of the
 * span simply hits (else LaneHit() tells each pixel's case).
 */
__attribute__((always_inline)) inline bool ClipSpanLanes(const CellRecord& cell,
  const TileRays& rays, size_t p, int count, const LaneOut& out, size_t q)
{
  using M4 = decltype(V4{} < V4{}); // per lane: all bits set (true) or 0
  using M2 = decltype(V2{} < V2{});
  M4 all4 = { -1, -1, -1, -1 };
  M2 all2 = { -1, -1 };
  int i = 0;
  for (; count - i >= 3; i += 4)
  {
    const M4 past = { 0, 0, 0, count - i >= 4 ? 0 : -1 }; // lanes past the end
    ClipPixelLanes<V4>(cell, rays, p + i, out, q + i, past, all4);
  }
  if (i < count)
  {
    const M2 past = { 0, count - i >= 2 ? 0 : -1 };
    ClipPixelLanes<V2>(cell, rays, p + i, out, q + i, past, all2);
  }
  return ((all4[0] & all4[1]) & (all4[2] & all4[3]) & (all2[0] & all2[1])) != 0;
}
#else
/// Without vector extensions: ClipRay() pixel by pixel (same results).
inline bool ClipSpanLanes(const CellRecord& cell, const TileRays& rays, size_t p, int count,
  const LaneOut& out, size_t q)
{
  bool all = true;
  for (int i = 0; i < count; ++i)
  {
    Ray ray;
    const size_t pi = p + i;
    ray.Origin = glm::dvec3(rays.OX[pi], rays.OY[pi], rays.OZ[pi]);
    ray.Direction = glm::dvec3(rays.DX[pi], rays.DY[pi], rays.DZ[pi]);
    double tIn = 0.0, tOut = 0.0;
    const bool hit = ClipRay(cell, ray, rays.TMax[pi], glm::dvec3(), glm::dvec3(), tIn, tOut);
    const double sAtOrigin = cell.RefScalar + glm::dot(cell.Gradient, ray.Origin - cell.RefPoint);
    const double slope = glm::dot(cell.Gradient, ray.Direction);
    out.TIn[q + i] = tIn;
    out.TOut[q + i] = tOut;
    out.SIn[q + i] = sAtOrigin + tIn * slope;
    out.SOut[q + i] = sAtOrigin + tOut * slope;
    out.Length[q + i] = tOut - tIn;
    if (out.Pixel)
    {
      out.Pixel[q + i] = static_cast<int>(pi);
      out.Interval[q + i] = cell.Interval;
    }
    all = all && hit && !IsUndecided(cell, ray);
  }
  return all;
}
#endif

#if defined(__GNUC__)
/**
 * ProjectedRowRange() for the tile rows [j0, j1] of a projectable cell (tile
 * origin x0, y0, width w), four rows per vector: the edges a row crosses
 * (strictly between its ends: a row through no vertex), their crossings and
 * the rounding to pixel centres as one row at a time, so the ranges are the
 * same; a group of rows with one through a vertex takes ProjectedRowRange().
 * Appends the non-empty rows' first pixel (j w + r0) and count to @p start
 * and @p count; returns how many.
 */
__attribute__((always_inline)) inline int RowRangesLanes(const ProjectedEdges& edges, int x0,
  int y0, int w, int i0, int i1, int j0, int j1, int* start, int* count)
{
  typedef int I4 __attribute__((vector_size(4 * sizeof(int))));
  constexpr double margin = hov::BoxMargin;
  const V4 limit = V4{} + 1073741824.0; // CeilToInt's clamp
  int rows = 0;
  for (int j = j0; j <= j1; j += 4)
  {
    const V4 y = V4{ 0.5, 1.5, 2.5, 3.5 } + static_cast<double>(y0 + j);
    const auto vertex = (y == edges.BandY[0]) | (y == edges.BandY[1]) | (y == edges.BandY[2]) |
      (y == edges.BandY[3]);
    if (vertex[0] | vertex[1] | vertex[2] | vertex[3])
    {
      for (int jj = j; jj <= std::min(j + 3, j1); ++jj)
      {
        int r0, r1;
        if (ProjectedRowRange(edges, y0 + jj + 0.5, x0, i0, i1, r0, r1))
        {
          start[rows] = jj * w + r0;
          count[rows++] = r1 - r0 + 1;
        }
      }
      continue;
    }
    V4 lo = V4{} + 1e300, hi = V4{} - 1e300;
    for (int e = 0; e < 6; ++e)
    {
      const auto meets = (edges.PY[e] - y) * (edges.QY[e] - y) <= 0.0;
      const V4 x = edges.PX[e] + edges.DX[e] * ((y - edges.PY[e]) * edges.InvDY[e]);
      lo = meets & (x < lo) ? x : lo;
      hi = meets & (hi < x) ? x : hi;
    }
    // CeilToInt / FloorToInt per lane.
    V4 c = (lo - 0.5) - margin, f = (hi - 0.5) + margin;
    c = c < -limit ? -limit : c;
    c = limit < c ? limit : c;
    f = f < -limit ? -limit : f;
    f = limit < f ? limit : f;
    const I4 ci = __builtin_convertvector(c, I4), fi = __builtin_convertvector(f, I4);
    const I4 up = __builtin_convertvector(__builtin_convertvector(ci, V4) < c, I4);
    const I4 down = __builtin_convertvector(f < __builtin_convertvector(fi, V4), I4);
    const I4 r0 = ci - up - x0, r1 = fi + down - x0; // true is -1
    const auto some = lo <= hi;
    for (int l = 0; l < 4 && j + l <= j1; ++l)
    {
      const int a = std::max(i0, r0[l]), b = std::min(i1, r1[l]);
      if (some[l] && a <= b)
      {
        start[rows] = (j + l) * w + a;
        count[rows++] = b - a + 1;
      }
    }
  }
  return rows;
}
#else
inline int RowRangesLanes(const ProjectedEdges& edges, int x0, int y0, int w, int i0, int i1,
  int j0, int j1, int* start, int* count)
{
  int rows = 0;
  for (int j = j0; j <= j1; ++j)
  {
    int r0, r1;
    if (ProjectedRowRange(edges, y0 + j + 0.5, x0, i0, i1, r0, r1))
    {
      start[rows] = j * w + r0;
      count[rows++] = r1 - r0 + 1;
    }
  }
  return rows;
}
#endif

}
}

using namespace hov::tile;

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__APPLE__)
#define HOV_SPAN_TARGET_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define HOV_SPAN_TARGET_CLONES
#endif
/// ClipSpanLanes(), compiled also for AVX2 (one instruction per four-pixel
/// operation), chosen at load time; the operations, hence the results, are
/// the same on every CPU.
HOV_SPAN_TARGET_CLONES
bool hov::tile::ClipSpan(
  const CellRecord& cell, const TileRays& rays, size_t p, int count, const LaneOut& out, size_t q)
{
  return ClipSpanLanes(cell, rays, p, count, out, q);
}

HOV_SPAN_TARGET_CLONES
int hov::tile::RowRanges(const ProjectedEdges& edges, int x0, int y0, int w, int i0, int i1,
  int j0, int j1, int* start, int* count)
{
  return RowRangesLanes(edges, x0, y0, w, i0, i1, j0, j1, start, count);
}

HOV_SPAN_TARGET_CLONES
bool hov::tile::ClipRows(const CellRecord& cell, const TileRays& rays, const int* start,
  const int* count, int rows, const LaneOut& out, size_t q)
{
  bool all = true;
  for (int r = 0; r < rows; ++r)
  {
    all = ClipSpanLanes(cell, rays, start[r], count[r], out, q) && all;
    q += count[r];
  }
  return all;
}


HOV_SPAN_TARGET_CLONES
vtkIdType hov::tile::CompositeQueue(const int* pixel, const double* tIn, const double* tOut,
  const hov::RGBA* results, const int* piecesOf, int n, const CompositeTarget& target,
  vtkIdType& pieces)
{
  // Everything through locals: byte stores (Done) may alias any member.
  hov::RGBA* accum = target.Accum;
  double* maxExit = target.MaxExit;
  unsigned char* violated = target.Violated;
  unsigned char* done = target.Done;
  const double tol = target.Tolerance;
  const double termination = target.Termination;
  vtkIdType segments = 0, added = 0;
  for (int m = 0; m < n; ++m)
  {
    const int p = pixel[m];
    if (done[p])
    {
      continue;
    }
    if (tIn[m] < maxExit[p] - tol)
    {
      violated[p] = 1;
    }
    maxExit[p] = std::max(maxExit[p], tOut[m]);
    hov::CompositeBehind(accum[p], results[m]);
    if (1.0 - accum[p].A <= termination)
    {
      done[p] = 1;
      ++target.DoneInRow[p / target.Width];
    }
    ++segments;
    added += piecesOf[m];
  }
  pieces += added;
  return segments;
}
