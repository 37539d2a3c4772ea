/**
 * @class   hov::GeneralCellTile
 * @brief   Per-thread work of the CPU projector on one general cell (voxel,
 *          hexahedron, wedge, pyramid, quadratic cells) in one image tile:
 *          scan conversion, exact ray/cell intervals and the accurate
 *          integral of each interval.
 *
 * Scan conversion: the candidate pixels of a row are the pixel centres in
 * the span of the convex hull of the projected corners (a straight-edged
 * cell, bilinear faces included, lies in the convex hull of its corners),
 * widened by BoxMargin pixels; the ray test that follows is exact. A cell with
 * a corner at or behind the eye plane takes its whole pixel box.
 *
 * Per pixel (Collect): hov::RayCellIntervals within the pixel's ray range
 * [0, tMax]: the inside intervals, sorted and disjoint (up to
 * hov::MaxRayCellIntervals for non-planar faces), with bit-identical
 * shared-face times (corner point ids), so there is no crack and no double
 * counting between neighbouring general cells. A triangle shared with a
 * linear tetrahedron gives bit-identical times too (hovRayCell evaluates
 * planar faces with the fast path's formula, corner order and operation
 * order). A ray lying exactly in a planar face's plane is given to exactly
 * one of the two cells sharing the face by the rays' symbolic perturbation
 * (FrameData::Perturbation = the rays' PerturbX/PerturbY, the tetrahedra's
 * rule: hovRayCell.h; TestMixedInFace, TestCellRayInFace).
 *
 * Per interval (Integrate): the scalar along the ray as polynomial pieces
 * (hov::RestrictCellScalar: exact for affine cells, Chebyshev with a bound of
 * Restriction.RelativeTolerance x the cell's scalar range otherwise), each
 * piece integrated by hov::IntegratePolynomialScalar (exact optical depth,
 * Gauss-Kronrod colour with error estimate <= Segment.Tolerance per channel;
 * degree <= 1 is the linear cells' closed form; past thousands of smooth
 * table nodes its sampled route, both within the estimate), pieces composited front to
 * back. A cell with a constant scalar (e.g. cell scalars) is one constant
 * piece per interval, with no restriction at all (exact).
 * Accuracy per interval: colour and opacity within Segment.Tolerance plus
 * the restriction bound times the transfer function's slope (both ~1e-9 or
 * better with the defaults); exact to rounding for affine cells with a field
 * of degree <= 1 along the ray.
 *
 * Cost (measured, 512x512, one core of a loaded 2-core machine, Release):
 * zoo_mixed_ccx.vtu (12.7k hexahedra/wedges/pyramids beside 56k tetrahedra)
 * 2.8 s CPU per frame, of which ~2.3 s for its 1.28M general-cell intervals
 * (~1.8 us each: polynomial integral ~45%, restriction ~20%, intervals
 * ~10%); tjunction_tet10_dolfinx.vtu (10.5k quadratic tetrahedra, 1.02M
 * intervals) 1.44 s (~1.4 us each). Linear tetrahedra cost ~0.1-0.2 us per
 * segment in comparison.
 *
 * Thread safety: one object per thread (the tile's); the frame data is shared
 * read-only. Scratch vectors keep their capacity: no allocation per pixel.
 * @sa hov::ProjectorTile, hov::GeneralCells, hovRayCell.h,
 * hovCellRestriction.h, hovPolynomialSegment.h
 */
#ifndef hovGeneralCellTile_h
#define hovGeneralCellTile_h

#include "hovViewRays.h" // Ray

#include "hovCellRestriction.h"   // RestrictedPiece, settings
#include "hovCompositing.h"       // RGBA
#include "hovPolynomialSegment.h" // settings
#include "hovRayCell.h"           // RayCellInterval

#include "vtkType.h" // vtkIdType

#include <array>  // pixel box
#include <vector> // scratch

namespace hov
{
class GeneralCells;
}
namespace hov
{
class TransferFunction;
}

namespace hov
{
class GeneralCellTile
{
public:
  /// What every tile of a frame reads about the general cells.
  struct FrameData
  {
    const hov::GeneralCells* Cells = nullptr;
    /// Per ordered cell: index into Cells->GetCells(), or -1 for a tetrahedron.
    const std::vector<int>* GeneralOf = nullptr;
    const glm::dvec2* Window = nullptr;          ///< projected points (window coordinates)
    const unsigned char* Projectable = nullptr;  ///< per point: in front of the eye plane
    const hov::TransferFunction* TF = nullptr;
    hov::PolynomialSegmentSettings Segment;
    hov::CellRestrictionSettings Restriction;
    /// Symbolic ray displacement deciding rays in a face plane (the rays'
    /// GetPerturbX/GetPerturbY, as for the tetrahedra: hovRayCell.h).
    hov::RayPerturbation Perturbation;
  };

  /// The rows of a tile the caller wants (tile-local pixel p = j W + i).
  struct TileRows
  {
    int X0, Y0, W, RowBegin, RowEnd;
    const hov::ViewRays::Ray* Rays; ///< per tile pixel
    const double* TMax;                    ///< per tile pixel
  };

  /// A covered pixel and its intervals (Intervals()[First .. First + Count)).
  struct Hit
  {
    int Pixel;
    int First;
    int Count;
  };

  /**
   * The pixels of @p rows covered by general cell @p g (pixel box @p box) and
   * their ray intervals, pixel by pixel in row order; pixels with
   * @p skip[p] != 0 (if @p skip is given) are not tested. Returns the hits
   * (valid until the next call).
   */
  const std::vector<Hit>& Collect(const FrameData& frame, int g, const std::array<int, 4>& box,
    const TileRows& rows, const unsigned char* skip);

  /// The intervals of the last Collect().
  const std::vector<hov::RayCellInterval>& Intervals() const { return this->IntervalList; }

  /**
   * Premultiplied RGBA of general cell @p g over [@p t0, @p t1] of @p ray
   * (an inside interval); @p pieces is incremented by the integrated pieces.
   */
  hov::RGBA Integrate(const FrameData& frame, int g, const hov::ViewRays::Ray& ray,
    double t0, double t1, vtkIdType& pieces);

  /**
   * The scalar of general cell @p g along [@p t0, @p t1] of @p ray as
   * polynomial pieces in t - T0 (the pieces Integrate() integrates; one
   * exact constant piece for a constant cell); valid until the next call.
   */
  const std::vector<hov::RestrictedPiece>& Restrict(
    const FrameData& frame, int g, const hov::ViewRays::Ray& ray, double t0, double t1);

  /// The rays' symbolic displacement (GetPerturbX, GetPerturbY) for FrameData.
  static hov::RayPerturbation PerturbationOf(const hov::ViewRays& rays);

  /// Pixel box of general cell @p g (pixel centres of its projected corners' box).
  static std::array<int, 4> PixelBox(
    const FrameData& frame, int g, int width, int height, bool& projectable);

private:
  std::vector<Hit> Hits;
  std::vector<hov::RayCellInterval> IntervalList;
  std::vector<hov::RestrictedPiece> Pieces;
};
}

#endif
