/**
 * @file hovRayCell.h
 * @brief Where a straight ray x(t) = o + t d is inside a straight-edged cell:
 * a sorted list of disjoint intervals [T0, T1] of t.
 *
 * The cell is the region bounded by its faces, taken from its corners
 * (GeometryShape of hovCellShapes.h; VTK 9.1 face lists): triangles are
 * planar; a quadrilateral face is planar if its 4 corners are exactly
 * coplanar (Orient3d == 0, hovGeometricPredicates.h), else it is the
 * bilinear patch of its corners (the boundary of the trilinear/wedge/pyramid
 * map, so the region is the image of the parametric domain).
 *
 * Shared faces, no cracks and no double counting: every t at which a ray
 * meets a face is computed by FaceRayCrossings from the face's corners put
 * in a CANONICAL order that depends only on the face (rotation so that the
 * smallest point id comes first, then the direction whose second id is the
 * smaller; ids tied -> coordinates compared lexicographically). The caller
 * passes the global point ids of the corners (cornerIds). Two cells sharing a
 * face therefore obtain bit-identical crossing times for it, and since every
 * interval end is one of these times (or the caller's tMin/tMax), the exit t
 * of one cell equals the entry t of the other EXACTLY.
 *  - Plane crossing (triangles, planar quads): n = (c1 - c0) x (c2 - c0)
 *    (triangle) or (c2 - c0) x (c3 - c1) (quad, diagonals),
 *    t = (n.c0 - n.o) / n.d (the formula, corner order and operation order of
 *    the linear-tetrahedron fast path, hov::CellSetup / hovTileGeometry.h:
 *    a triangle shared by a tetrahedron of that path and a general cell gives
 *    bit-identical crossing times; for a triangle, ascending ids = the
 *    canonical order); n.d == 0: no crossing (parallel).
 *  - Bilinear patch P(u,v) = c0 + u e10 + v e01 + uv q (e10 = c1 - c0,
 *    e01 = c3 - c0, q = c2 - c1 - c3 + c0): eliminating t and v gives
 *      u^2 d.(e10 x q) + u [d.((c0-o) x q) + d.(e10 x e01)] + d.((c0-o) x e01) = 0
 *    solved by FindRoots (hovPolynomial.h: cancellation-free, a -> 0 safe,
 *    tangency reported once) for u in [-PatchSlack, 1 + PatchSlack]; then
 *    v = -((P0 x d).(E x d)) / |E x d|^2, t = d.(P0 + v E) / |d|^2 with
 *    P0 = c0 - o + u e10, E = e01 + u q. A ray can cross a patch twice.
 *
 * Cells whose faces are all planar (tetrahedra always): half-space clipping,
 * tIn = max over entering faces, tOut = min over leaving faces (entering if
 * n.d has the sign of n.(centroid - c0)); a ray parallel to a face plane and
 * on its outer side misses. One interval at most.
 *
 * Rays lying in a face plane (n.d == 0 and n.c0 - n.o == 0 exactly): the ray
 * is displaced symbolically by e X + e^2 Y (e -> 0+, RayPerturbation; the
 * renderer passes hov::ViewRays' PerturbX/PerturbY, the rule of the
 * tetrahedron fast path): it lies on the side of sign(n.X), or sign(n.Y) if
 * n.X == 0 (neither: outside). Two cells sharing a planar face compute the
 * same canonical n and opposite sides, so exactly one of them takes the ray
 * (no crack, no double counting). Overloads without a perturbation use
 * DefaultRayPerturbation(d). Rays not in a face plane are not affected.
 * Cells with a non-planar quad (classified by midpoints, below): a ray in the
 * plane of one of their PLANAR faces (n.d == 0, |n.c0 - n.o| within rounding)
 * has its midpoints pushed off the plane by 1e-7 of the face's extent to the
 * side given by the sign of n.c0 - n.o or, if 0, the perturbation; the push
 * depends only on the face, so the neighbour across it decides the same
 * side (points within that distance of another face of the cell may be
 * misclassified). A ray lying IN a non-planar bilinear patch touches it along
 * a ruling (a set of rays of measure zero): no tie rule, its crossings are
 * whatever FindRoots reports and both neighbours may count or skip it.
 *
 * Cells with a non-planar quad: all crossings (extra candidates, e.g. a plane
 * or patch met outside the face, only split intervals and are harmless;
 * crossings are never missed thanks to the slack) are sorted with tMin and
 * tMax, and each gap between successive candidates is classified by its
 * midpoint: inside iff InvertGeometry converges there with
 * ParametricDistanceOutside <= InsideSlack. Adjacent inside gaps merge. A
 * ray may enter and leave such a cell twice (MaxRayCellIntervals).
 * Gaps shorter than the classification's resolution are irrelevant (their
 * length is ~1e-12 of the cell size at most).
 *
 * Measured (TestCellRay): random rays agree with a brute-force inside test
 * (Newton inversion at 401 points per ray, 1e-7 from the ends excluded) for
 * planar and perturbed (non-planar) hexahedra, wedges, pyramids; two
 * perturbed hexahedra sharing a non-planar face, corners listed in different
 * VTK orders: exit t == entry t bit for bit on 1995 of 2000 rays from one
 * cell into the other (the other 5 leave the pair through another face in
 * between; no overlap on any ray).
 *
 * Domain: finite corners, d != 0, tMin <= tMax finite. Degenerate rays
 * (through vertices or edges, in a face plane) give no NaN: zero-length
 * intervals are dropped.
 *
 * Thread safety: re-entrant; no allocation.
 * @sa hovCellShapes.h, hovCellRestriction.h, hovGeometricPredicates.h
 */
#ifndef hovRayCell_h
#define hovRayCell_h

#include "hovCellShapes.h"
#include "hovConfig.h"

#include <cstdint> // std::int64_t point ids

namespace hov
{
/// Intervals returned at most (a ray crosses each non-planar face <= 2 times).
constexpr int MaxRayCellIntervals = 8;
/// Parametric slack of the patch crossing test (u outside [0,1] by this is still a candidate).
constexpr double PatchSlack = 1e-6;
/// A gap midpoint is inside if it lies at most this far outside the parametric domain.
constexpr double InsideSlack = 1e-9;

/**
 * Symbolic displacement of a ray, o + e X + e^2 Y (e -> 0+), deciding rays
 * that lie exactly in a face plane. X, Y and the ray direction must be
 * linearly independent.
 */
struct RayPerturbation
{
  double X[3] = { 1.0, 0.0, 0.0 };
  double Y[3] = { 0.0, 1.0, 0.0 };
};

/// A valid perturbation for direction @p d: X the axis of d's smallest
/// component, Y = d x X. Used by the overloads without a perturbation.
HOV_EXPORT RayPerturbation DefaultRayPerturbation(const double direction[3]);

/// One inside interval of the ray.
struct RayCellInterval
{
  double T0 = 0.0;
  double T1 = 0.0;
};

/**
 * Crossing times of the ray with one face (3 or 4 corners in cyclic order,
 * with their point ids), canonical and order-independent (see file doc).
 * Writes up to 2 values into @p t (ascending); returns their number.
 */
HOV_EXPORT int FaceRayCrossings(int cornerCount, const double* const corners[4],
  const std::int64_t ids[4], const double origin[3], const double direction[3], double t[2]);

/// FaceRayCrossings() for a face whose planarity (IsQuadPlanar) is known.
HOV_EXPORT int FaceRayCrossingsKnown(int cornerCount, const double* const corners[4],
  const std::int64_t ids[4], const double origin[3], const double direction[3], double t[2],
  bool planar);

/// True if the 4 corners are exactly coplanar (then the face is a plane).
HOV_EXPORT bool IsQuadPlanar(const double* const corners[4]);

/**
 * Bit f set iff face f (CellFaceCorners order) of the cell is planar
 * (triangles always; quads by IsQuadPlanar). View-independent: callers that
 * cast many rays through one cell compute it once and pass it to
 * RayCellIntervals, saving the exact predicates per ray.
 */
HOV_EXPORT unsigned PlanarFaceMask(CellShape shape, const double* points);

/**
 * Inside intervals of the ray o + t d, t in [@p tMin, @p tMax], for the cell
 * @p shape with corner coordinates @p points (3 per node, VTK order; only
 * corners read) and corner point ids @p cornerIds. Writes at most
 * MaxRayCellIntervals sorted disjoint intervals of positive length to
 * @p out; returns their number (0: the ray misses).
 */
HOV_EXPORT int RayCellIntervals(CellShape shape, const double* points,
  const std::int64_t* cornerIds, const double origin[3], const double direction[3], double tMin,
  double tMax, RayCellInterval* out);

/// RayCellIntervals() with the faces' planarity given (PlanarFaceMask(shape,
/// points)): the same result without recomputing it.
HOV_EXPORT int RayCellIntervals(CellShape shape, const double* points,
  const std::int64_t* cornerIds, const double origin[3], const double direction[3], double tMin,
  double tMax, RayCellInterval* out, unsigned planarFaces);

/// RayCellIntervals() with the tie rule of rays in a face plane given
/// (@p perturbation: see the file doc).
HOV_EXPORT int RayCellIntervals(CellShape shape, const double* points,
  const std::int64_t* cornerIds, const double origin[3], const double direction[3], double tMin,
  double tMax, RayCellInterval* out, unsigned planarFaces, const RayPerturbation& perturbation);

/// Faces of a cell (by GeometryShape): count, and the corners of face @p f.
HOV_EXPORT int CellFaceCount(CellShape shape);
/// Corner indices of face @p f in cyclic order; returns 3 or 4.
HOV_EXPORT int CellFaceCorners(CellShape shape, int f, int corners[4]);
}

#endif
