/**
 * @file hovCurvedRayCell.h
 * @brief Where a straight ray x(t) = o + t d is inside a CURVED Lagrange
 * cell: every inside interval [T0, T1] of t, sorted nearest first, with the
 * parametric coordinates at both ends (warm starts for the field).
 *
 * Method (the curved counterpart of hovRayCell.h's non-planar path):
 *  1. all crossings of the ray with the cell's boundary patches
 *     (FaceRayCrossings of hovCurvedFaces.h: Bernstein exclusion, interval
 *     uniqueness, Newton on the exact map; ALL roots, not the first), kept
 *     if inside (tMin, tMax);
 *  2. sorted; crossings closer than MergeRelative x extent / |d| in t are
 *     one (a ray through an edge meets two patches there);
 *  3. each gap between consecutive candidates (tMin, crossings, tMax) is
 *     classified by its midpoint: inside iff InvertLagrangeGeometry
 *     (hovLagrangeCell.h, warm-started from the gap's end coordinates)
 *     converges there with DistanceOutside <= InsideSlack (1e-12);
 *  4. adjacent inside gaps merge.
 * A ray that leaves and re-enters the cell (curved faces) gets several
 * intervals; a grazing ray touching a face gives a crossing pair of (near)
 * zero length or a single contact, neither of which creates a spurious
 * interval (the gaps on both sides are classified by their midpoints).
 * Spurious or missing crossings can only split or shorten intervals by the
 * length of a gap whose midpoint is misclassified; with Complete = true and
 * no inversion failure no crossing is missing (up to the face search's
 * resolution, 2^-22 of a face).
 *
 * Where the geometry is affine (or the cell is a trilinear hexahedron of
 * any order with nodes on the trilinear map), the faces are the planes /
 * bilinear patches of hovRayCell.h and the intervals agree with
 * RayCellIntervals to ~1e-13 of the cell size.
 * Measured (TestCurvedRayCell, GCC 12 Release): max |t - t_ref| 2.0e-14
 * against RayCellIntervals (720 rays, tet/hex/wedge of orders 1..4 with
 * straight-sided geometry, non-planar quads); 0 disagreements with a
 * brute-force inside test on curved cells of every type, orders 1..5; the
 * arch test (re-entry: 2 intervals, ends within 1e-12 of the closed form;
 * grazing from inside: 1 interval; 1e-8 below the apex: 2 intervals, gap
 * within 1e-9 of 2 sqrt(1e-8/0.6); grazing from outside: nothing).
 * Cost, unoptimised: ~60-70 us per ray and cell (orders <= 5, shared
 * machine); the face nets are built per cell by BuildCurvedFaces.
 *
 * Domain: finite o, d != 0, tMin <= tMax finite (clip to the cell's bounding
 * box first), faces from BuildCurvedFaces(cell).
 *
 * Thread safety: re-entrant; the crossings are collected in @p scratch (or a
 * local vector if null).
 * @sa hovCurvedFaces.h, hovRayCell.h, hovLagrangeCell.h
 */
#ifndef hovCurvedRayCell_h
#define hovCurvedRayCell_h

#include "hovConfig.h"
#include "hovCurvedFaces.h"
#include "hovCurvedSharedFaces.h" // SharedFaceContext
#include "hovLagrangeCell.h"

#include <vector> // crossings scratch

namespace hov
{
/// One inside interval with the parametric coordinates at its ends.
struct CurvedRayInterval
{
  double T0 = 0.0, T1 = 0.0;
  double PC0[3] = { 0.0, 0.0, 0.0 };
  double PC1[3] = { 0.0, 0.0, 0.0 };
};

struct CurvedRaySettings
{
  FaceSearchSettings Faces;
  /// Parametric distance outside still counted inside: far below the length of
  /// any gap that matters (a 1e-9 gap at a bounding-box clip must stay outside).
  double InsideSlack = 1e-12;
  double MergeRelative = 1e-12;  ///< crossings closer than this x extent (in x) are one
};

struct CurvedRayStatus
{
  int Crossings = 0;          ///< distinct crossings in (tMin, tMax)
  int Grazing = 0;            ///< of which found at the resolution limit
  int Patches = 0;            ///< sub-patches examined
  int InversionFailures = 0;  ///< gap midpoints where Newton failed (taken as outside)
  bool Complete = true;       ///< the face search finished within its budget
};

/**
 * Inside intervals of the ray o + t d, t in [@p tMin, @p tMax], written to
 * @p out (at most @p maxOut, nearest first; see file doc). Returns their
 * number. With @p shared, a face the ray's cache already holds (searched by
 * the neighbour) is not searched again, and the faces searched here are
 * stored for the neighbour (hovCurvedSharedFaces.h).
 */
HOV_EXPORT int RayCurvedCellIntervals(const LagrangeCellView& cell, const CurvedCellFaces& faces,
  const double origin[3], const double direction[3], double tMin, double tMax,
  CurvedRayInterval* out, int maxOut, const CurvedRaySettings& settings = CurvedRaySettings(),
  CurvedRayStatus* status = nullptr, std::vector<FaceCrossing>* scratch = nullptr,
  const SharedFaceContext* shared = nullptr);
}

#endif
