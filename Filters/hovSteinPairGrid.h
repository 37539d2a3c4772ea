/**
 * @file hovSteinPairGrid.h
 * @brief The per-view face data and the uniform screen grid of the boundary
 *        pair search of vtkSteinVisibilitySort (hovSteinBoundaryPairs.h), shared
 *        with the covering sheets that prune it (hovSteinSheets.h).
 *
 * A grid tile is the set of screen points whose IX() and IY() are its column
 * and row: a rectangle (IX and IY are monotone), the border tiles extended to
 * infinity outwards (IX and IY clamp). Every test that reasons about "the
 * points of a tile" uses these functions, never a rectangle computed apart.
 */
#ifndef hovSteinPairGrid_h
#define hovSteinPairGrid_h

#include "hovSteinBuffers.h" // FillBuffer

#include "vtkType.h" // vtkIdType

#include <cmath>   // std::abs
#include <cstdint> // std::uint8_t, std::int16_t, std::int32_t

namespace hovStein
{
/**
 * Per-view data of one face of the pair search: screen corners, extents, depth
 * range, corner ids. Two cache lines: the first holds all that the screen
 * tests of a face pair read (ApartOnScreen, InFrontOnScreen: corners, scale,
 * extent, flags), so a pair of faces met in random order loads one line of
 * each; the second the extents, depths and ids (records, sheets, planes).
 */
struct alignas(64) FaceData
{
  double Corners[3][2]; ///< screen points of the first three corners if Screen
  /// If Screen: the magnitude the rounding of Corners is relative to (the
  /// world coordinates in a parallel view, 1 + |screen coordinates| in a
  /// perspective one, whose screen points are tangents), rounded up.
  float ScreenScale;
  float Extent; ///< if Screen: the larger side of the first three corners' extents, rounded up
  std::uint8_t NumIds;
  std::uint8_t Exact;       ///< 1: Ids[TripleAt[0..2]] span the exact face plane
  std::uint8_t Screen;      ///< 1: Box, depths and Corners are the face's (its cell is visible)
  std::uint8_t TripleAt[3]; ///< if Exact: the exact plane's corners (outward counterclockwise)
  float Box[4];         ///< xmin, xmax, ymin, ymax (outward)
  double Front, Rear;
  vtkIdType Ids[4]; ///< corners (point ids)
};
static_assert(sizeof(FaceData) == 128, "two cache lines");

/**
 * The pair search's rounding margin on depth comparisons: a depth moved by
 * 1e-9 of its magnitude and of the mesh's diagonal @p diagonal, towards the
 * eye (DepthBefore) or away from it (DepthAfter).
 */
inline double DepthBefore(double z, double diagonal)
{
  return z - 1e-9 * (std::abs(z) + diagonal);
}
inline double DepthAfter(double z, double diagonal)
{
  return z + 1e-9 * (std::abs(z) + diagonal);
}

/// The most tiles of the pair search's grid on a side.
constexpr int MaxGridSide = 4096;

/// Uniform screen grid of the pair search.
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
  vtkIdType NumberOfTiles() const { return static_cast<vtkIdType>(this->NX) * this->NY; }
};

struct View;
/// Tiles about the mean extent of the faces @p data, within the view
/// window of @p v, at most ~4 per face.
PairGrid MakePairGrid(const View& v, const FillBuffer<FaceData>& data);

/// A face in the lists of the tiles: what the pair search rejects on, stored
/// contiguously in tile order (the search streams through them; the covering
/// sheets read their ENTRY faces from them).
struct TileRecord
{
  float Box[4];
  double Depth; ///< ENTRY: rear depth; EXIT: DepthBefore(front depth)
  /// ENTRY: DepthBefore(front depth); EXIT: DepthAfter(rear depth) (the
  /// covering sheets' tests; the ENTRY records' order where the faces overlap deeply).
  double Far;
  std::int32_t Cell; ///< (a CellIndex)
  std::uint32_t Face; ///< index into the faces (at most 6 a cell: fits)
  /// The face's tiles (TileRange; at most MaxGridSide a side): IX and
  /// IY are monotone, so the tile of max(x0 of two faces) is the max of their
  /// first tile columns, etc.
  std::int16_t Tiles[4];
};
static_assert(sizeof(TileRecord) == 48, "compact records: the search streams through them");
static_assert(MaxGridSide <= 32767, "tile columns and rows fit in 16 bits");
}

#endif
