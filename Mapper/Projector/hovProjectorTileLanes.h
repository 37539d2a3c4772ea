/**
 * @file    hovProjectorTileLanes.h
 * @brief   Private to hov::ProjectorTile: exact ray clipping of a row
 *          of pixels against a cell, several pixels per vector instruction,
 *          written straight into the tile's segment queue, and the
 *          compositing of the queue (CompositeQueue).
 *
 * Declarations and small inline helpers, in namespace hov::tile; the
 * vector code is in hovProjectorTileLanes.cxx.
 * @sa hov::ProjectorTile, hovTileGeometry.h
 */
#ifndef hovProjectorTileLanes_h
#define hovProjectorTileLanes_h

#include "hovTileGeometry.h" // ClipRay, IsUndecided, RowSpan

namespace hov::tile
{
using TileRays = hov::ProjectorTile::TileRays;
constexpr int PixelLanes = 4; ///< pixels per full block of lanes (the rays' padding)

/// Where clipped pixel lanes are written: the segment's ends, the scalar at
/// both and its length tOut - tIn, one array each (index = lane).
struct LaneOut
{
  double *TIn, *TOut, *SIn, *SOut, *Length;
  int* Pixel;    ///< the lane's pixel (if not null)
  int* Interval; ///< the cell's transfer-function interval (with Pixel)
};

/**
 * ClipRay() and the scalars at both ends of the segment for the pixels
 * [p, p + count) of a row, several pixels per vector instruction with the
 * scalar code's operations (bit-identical), written at [q, q + count) of
 * @p out (up to PixelLanes - 1 lanes more are written: the arrays are padded,
 * as are the tile's rays). Returns true if every pixel of the span simply
 * hits (else LaneHit() tells each pixel's case). In
 * hovProjectorTileLanes.cxx (also compiled for AVX2); hidden:
 * called directly, not through the library's symbol table.
 */
#if defined(__GNUC__)
__attribute__((visibility("hidden")))
#endif
bool ClipSpan(
  const CellRecord& cell, const TileRays& rays, size_t p, int count, const LaneOut& out, size_t q);

/**
 * ClipSpan() for @p rows rows of a cell, one call per cell (the cell's
 * planes and field are set up once for all its rows): row r's pixels
 * [start[r], start[r] + count[r]) are written one row after the other from
 * @p q. Returns true if every pixel of every row simply hits.
 */
#if defined(__GNUC__)
__attribute__((visibility("hidden")))
#endif
bool ClipRows(const CellRecord& cell, const TileRays& rays, const int* start, const int* count,
  int rows, const LaneOut& out, size_t q);

/// The tile's pixels that CompositeQueue() composites into.
struct CompositeTarget
{
  hov::RGBA* Accum;
  double* MaxExit;
  unsigned char* Violated;
  unsigned char* Done;
  int* DoneInRow;     ///< per tile row: pixels done
  int Width;          ///< of the tile
  double Tolerance;   ///< the witness tolerance
  double Termination; ///< transmittance at which a pixel is done
};

/**
 * Composite the @p n queued segments (pixel, ends, RGBA, pieces) in queue
 * order, skipping pixels that turned opaque meanwhile: exactly what
 * compositing one segment at a time does (TilePixels::Witness(),
 * CompositeBehind()). Returns the number composited and adds their pieces
 * to @p pieces. In hovProjectorTileLanes.cxx (also compiled for AVX2: one
 * instruction per RGBA operation, the same results).
 */
#if defined(__GNUC__)
__attribute__((visibility("hidden")))
#endif
vtkIdType CompositeQueue(const int* pixel, const double* tIn, const double* tOut,
  const hov::RGBA* results, const int* piecesOf, int n, const CompositeTarget& target,
  vtkIdType& pieces);

/**
 * The case of one pixel of a span that did not simply hit, from what the
 * lanes wrote (@p tIn, @p tOut) and the ray: 1 hit, 0 miss, -1 undecided.
 */
inline int LaneHit(const CellRecord& cell, const Ray& ray, double tIn, double tOut)
{
  return IsUndecided(cell, ray) ? -1 : (tIn < tOut ? 1 : 0);
}

}

namespace hov::tile
{
/// The tile columns [r0, r1] (tile coordinates; box columns [i0, i1]) of
/// the pixel centres of the row at height @p y inside a projectable cell
/// (BoxMargin of slack); false if none.
inline bool ProjectedRowRange(
  const ProjectedEdges& edges, double y, int x0, int i0, int i1, int& r0, int& r1)
{
  double xMin, xMax;
  if (!RowSpan(edges, y, xMin, xMax))
  {
    return false;
  }
  constexpr double margin = hov::BoxMargin;
  r0 = std::max(i0, CeilToInt(xMin - 0.5 - margin) - x0);
  r1 = std::min(i1, FloorToInt(xMax - 0.5 + margin) - x0);
  return r0 <= r1;
}

/**
 * ProjectedRowRange() for the tile rows [j0, j1] of a projectable cell (tile
 * origin x0, y0, width w), several rows per vector instruction with the same
 * results. Appends the non-empty rows' first pixel (j w + r0) and count to
 * @p start and @p count; returns how many. In
 * hovProjectorTileLanes.cxx (also compiled for AVX2).
 */
#if defined(__GNUC__)
__attribute__((visibility("hidden")))
#endif
int RowRanges(const ProjectedEdges& edges, int x0, int y0, int w, int i0, int i1, int j0, int j1,
  int* start, int* count);
}

/// (Inline: called per row of every cell.)
inline bool hov::ProjectorTile::RowRange(
  const CellRecord& cell, const hov::tile::ProjectedEdges& edges, int j, int& r0, int& r1) const
{
  const Box& b = cell.PixelBox;
  r0 = std::max(b[0], this->X0) - this->X0;
  r1 = std::min(b[1], this->X0 + this->W - 1) - this->X0;
  if (cell.Projectable)
  {
    return hov::tile::ProjectedRowRange(edges, this->Y0 + j + 0.5, this->X0, r0, r1, r0, r1);
  }
  return r0 <= r1;
}

#endif
