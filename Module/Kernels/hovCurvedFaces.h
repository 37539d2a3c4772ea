/**
 * @file hovCurvedFaces.h
 * @brief The faces of a curved Lagrange cell as polynomial patches, and
 * every crossing of a straight ray with such a patch, found robustly
 * (Bernstein exclusion + interval uniqueness test + Newton on the exact map).
 *
 * The boundary of a cell is covered by one polynomial patch per face
 * (hexahedron 6 quadrilaterals; wedge 3 quadrilaterals + 2 triangles;
 * tetrahedron 4 triangles). Patch k is parametrised by (u, v) through a
 * bilinear map into the cell's parametric space,
 *   pc(u, v) = P00 (1-u)(1-v) + P10 u (1-v) + P01 (1-u) v + P11 u v,
 * on [0, 1]^2 for a quadrilateral; a triangle has P11 = P10 + P01 - P00 (the
 * map is affine) and its domain is u, v >= 0, u + v <= 1. So x(u, v) =
 * x(pc(u, v)) is a tensor polynomial of degree (DegreeU, DegreeV) on a
 * quadrilateral (the cell's orders along the face) and a polynomial of total
 * degree n = DegreeU = DegreeV on a triangle. Its Bernstein control net (tensor,
 * or triangular: hovCurvedTriangleNets.h) is computed from x at the
 * equispaced points (i / DegreeU, j / DegreeV), or (j / n, k / n) with j + k <=
 * n; the conversion amplifies rounding by <= ~4e3 at degree 10, so the
 * exclusion test below uses a margin of NetMargin = 1e-9 x extent.
 *
 * Ray-patch crossings (FaceRayCrossings): with e1, e2 orthonormal and
 * perpendicular to d, the ray is the zero set of
 *   h(u, v) = (e1 . (x(u,v) - o), e2 . (x(u,v) - o)).
 * Sub-patches ([u0,u1] x [v0,v1], or sub-triangles; the net restricted by
 * de Casteljau) are examined depth first:
 *  - exclusion: 0 outside the bounding box of either component's net
 *    (widened by the margin), or beyond a line along the normal of an edge of
 *    the corner control points' polygon or along their mean => no crossing
 *    (convex hull property);
 *  - uniqueness: the interval 2x2 Jacobian of h over the sub-patch (ranges
 *    of the derivative nets; on a sub-triangle, the derivatives along two of
 *    its edges), or the cones of the derivative nets, give a determinant that
 *    keeps its sign => at most one zero (interval mean value theorem); Newton
 *    on the net from the zero of the corners' interpolant must converge
 *    inside the sub-patch widened by 1e-9 (else split), and the crossing is
 *    then evaluated on the EXACT map (shape functions, not the net);
 *  - otherwise split at the middle of the side (a sub-triangle: the edge)
 *    along which h varies most (range of the derivative nets: a face
 *    parallel to the ray, e.g. the side of an extruded mesh seen along the
 *    extrusion, varies along one direction only and is split along it
 *    only), down to MinSize = 2^-22
 *    or until h varies by less than the margin along the side (the
 *    uniqueness test fails only near a tangency, where the ray grazes the
 *    face, or on faces parallel to the ray): a sub-patch that cannot be
 *    split and is not excluded reports its Newton result, or its centre if
 *    the net's image lies within GrazeTolerance (1e-8 x extent) of the ray
 *    (Grazing = true); MaxPatches bounds the work (Complete = false beyond).
 * The net's rounding (relative ~1e-12) is far below the margins, so the
 * exclusion and uniqueness decisions are those of exact arithmetic except
 * for sub-patches within ~1e-12 x extent of a decision boundary.
 * Crossing times t = d . (x - o) / |d|^2 on the exact map; Newton stops at
 * a step < 1e-15 (u, v) or a residual at its rounding floor.
 * Crossings of one patch at the same parametric point (within 1e-9; within
 * 64 MinSize for grazing ones) are merged.
 *
 * Thread safety: re-entrant; BuildCurvedFaces allocates the patches.
 * @sa hovCurvedRayCell.h, hovLagrangeCell.h, hovBernstein.h
 */
#ifndef hovCurvedFaces_h
#define hovCurvedFaces_h

#include "hovConfig.h"
#include "hovLagrangeCell.h"

#include <vector> // patch storage

namespace hov
{
/// Largest face degree per direction.
constexpr int MaxFaceDegree = MaxLagrangeOrder;

/// One face as a polynomial patch (see file doc).
struct CurvedFacePatch
{
  double P00[3], P10[3], P01[3], P11[3]; ///< bilinear map (u,v) -> pc
  bool Triangle = false;                  ///< a triangular face (see file doc)
  int DegreeU = 1, DegreeV = 1;
  /// +1 if x_u x x_v points out of the cell, -1 if into it (the patch's
  /// orientation in parametric space times the sign of det J at its centre;
  /// det J keeps its sign on a valid cell), 0 if det J vanishes there.
  int Orientation = 0;
  /// Box (xmin, xmax, ymin, ymax, zmin, zmax) of the net widened by
  /// NetMargin x extent: a ray missing it misses the patch.
  double Box[6] = { 0, 0, 0, 0, 0, 0 };
  /// Control net of x: Net[3 * ((DegreeV + 1) * a + b) + c], a along u, b
  /// along v; a triangle's: Net[3 * TriangleNetIndex(n, j, k) + c], j the
  /// power of u, k of v (hovCurvedTriangleNets.h).
  std::vector<double> Net;
};

/// The face patches of one cell plus its extent (the scale of every tolerance).
struct CurvedCellFaces
{
  std::vector<CurvedFacePatch> Faces;
  /// The cell's faces as ranges of patches: face k is Faces[FaceFirstPatch[k]]
  /// .. Faces[FaceFirstPatch[k + 1] - 1] (one patch per face at present).
  std::vector<int> FaceFirstPatch;
  double Extent = 0.0;
  /// Box (xmin, xmax, ymin, ymax, zmin, zmax) of every control point, widened
  /// by NetMargin x extent: it contains the cell (whose boundary lies in the
  /// convex hull of the nets).
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
};

/// Face patches of @p cell. False for an uninitialised basis.
HOV_EXPORT bool BuildCurvedFaces(const LagrangeCellView& cell, CurvedCellFaces& out);

/// pc(u, v) of @p face and, if given, its derivatives dpc/du, dpc/dv.
HOV_EXPORT void FaceParametricPoint(const CurvedFacePatch& face, double u, double v,
  double pc[3], double* dpcdu = nullptr, double* dpcdv = nullptr);

/// One crossing of a ray with a face.
struct FaceCrossing
{
  double T = 0.0;       ///< ray parameter (x = o + T d)
  double U = 0.0, V = 0.0;
  double PC[3] = { 0.0, 0.0, 0.0 }; ///< cell parametric coordinates of the point
  int Face = -1;
  bool Grazing = false; ///< found at the resolution limit (tangency or degenerate corner)
  /// -1 the ray enters the cell here, +1 it leaves, 0 undecided (grazing, or
  /// |d . n| <= SideTolerance |d| |n| with n = x_u x x_v, or no orientation).
  int Side = 0;
};

/// Relative |d . n| below which a crossing's Side is undecided.
constexpr double SideTolerance = 1e-6;

struct FaceSearchSettings
{
  double MinSize = 1.0 / 4194304.0; ///< 2^-22: smallest sub-patch side
  int MaxPatches = 20000;           ///< sub-patches examined per face before giving up
  double NetMargin = 1e-9;          ///< exclusion margin, relative to the extent
  double GrazeTolerance = 1e-8;     ///< relative distance of a grazing contact
};

struct FaceSearchStatus
{
  int Patches = 0;     ///< sub-patches examined
  bool Complete = true; ///< false if MaxPatches ran out (crossings may be missing)
};

/**
 * Every crossing of the ray o + t d (any t) with face @p f of @p faces,
 * appended to @p out (see file doc). Returns the number appended.
 */
HOV_EXPORT int FaceRayCrossings(const LagrangeCellView& cell, const CurvedCellFaces& faces,
  int f, const double origin[3], const double direction[3], std::vector<FaceCrossing>& out,
  const FaceSearchSettings& settings = FaceSearchSettings(), FaceSearchStatus* status = nullptr);
}

#endif
