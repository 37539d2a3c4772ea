/**
 * @file hovGeometricPredicates.h
 * @brief Exact orientation predicates on double coordinates (filtered).
 *
 * Orient2d(a, b, c) is the sign of
 *   | ax-cx  ay-cy |
 *   | bx-cx  by-cy |
 * : +1 when a, b, c turn counterclockwise, -1 clockwise, 0 when collinear.
 *
 * Orient3d(a, b, c, d) is the sign of det[a-d; b-d; c-d] (Shewchuk's
 * convention): +1 when d lies below the plane of a, b, c, where "above" is the
 * side from which a, b, c appear counterclockwise; -1 above; 0 coplanar. So
 * for a face a, b, c ordered counterclockwise seen from outside (outward
 * normal (b-a)x(c-a)), a point d is outside when Orient3d(a, b, c, d) < 0.
 *
 * Orient3dDirection(a, b, c, w) is the sign of Orient3d(a, b, c, a + s w) for
 * s -> +infinity, i.e. -sign(det[b-a; c-a; w]): the side of the point at
 * infinity in direction w (used for eyes at infinity, parallel projection).
 *
 * Every result is the exact sign for the given doubles: the determinant is
 * first evaluated in double and accepted when its magnitude exceeds
 * Shewchuk's a-priori bound (errboundA = (3 + 16 eps) eps |permanent| in 2D,
 * (7 + 56 eps) eps |permanent| in 3D, eps = 2^-53); otherwise (and whenever
 * the permanent is so small that products may have underflowed, or not
 * finite) it is recomputed exactly: when the differences are exact doubles,
 * in double if every product and sum of the cofactor expansion is checked
 * exact (fma residuals and sum tails zero: points of integer or dyadic grids,
 * e.g. corners lying exactly on other faces' planes), else with Shewchuk's
 * expansions; with rational arithmetic when even the differences round.
 * Non-finite inputs give 0.
 *
 * Thread safety: re-entrant.
 */
#ifndef hovGeometricPredicates_h
#define hovGeometricPredicates_h

#include "hovConfig.h"

namespace hov
{
/// Exact sign of the 2D orientation determinant (see file doc).
HOV_EXPORT int Orient2d(const double a[2], const double b[2], const double c[2]);

/// Exact sign of the 3D orientation determinant det[a-d; b-d; c-d].
HOV_EXPORT int Orient3d(const double a[3], const double b[3], const double c[3], const double d[3]);

/// Exact side of the point at infinity in direction w: -sign(det[b-a; c-a; w]).
HOV_EXPORT int Orient3dDirection(
  const double a[3], const double b[3], const double c[3], const double w[3]);

/**
 * Orient3d against an axis-aligned plane without the determinant. If a, b, c
 * are finite and share their coordinate k exactly, sets @p k and @p sigma,
 * the exact sign of ((b-a)x(c-a))_k (Orient2d of the two other coordinates,
 * cyclically: 0 when the triangle is degenerate), and returns true. Then
 * (b-a)x(c-a) = (0, ..., n_k, ..., 0) exactly, so for every d
 * Orient3d(a, b, c, d) == AxisOrient3d(k, sigma, a, d): two comparisons
 * instead of a determinant that points on the plane (grid-aligned meshes)
 * make the filter fail on. False otherwise (call Orient3d).
 */
HOV_EXPORT bool AxisAlignedPlane(
  const double a[3], const double b[3], const double c[3], int& k, int& sigma);

/// Orient3d(a, b, c, d) for the plane of AxisAlignedPlane(a, b, c, k, sigma).
inline int AxisOrient3d(int k, int sigma, const double a[3], const double d[3])
{
  // Non-finite d: 0, as Orient3d (NaN - NaN is not 0; inf - inf is NaN).
  if (!(d[0] - d[0] == 0 && d[1] - d[1] == 0 && d[2] - d[2] == 0))
  {
    return 0;
  }
  return sigma * (static_cast<int>(a[k] > d[k]) - static_cast<int>(a[k] < d[k]));
}

///@{
/// The exact (rational) evaluations alone, bypassing the floating-point filter.
HOV_EXPORT int Orient2dExact(const double a[2], const double b[2], const double c[2]);
HOV_EXPORT int Orient3dExact(
  const double a[3], const double b[3], const double c[3], const double d[3]);
HOV_EXPORT int Orient3dDirectionExact(
  const double a[3], const double b[3], const double c[3], const double w[3]);
///@}
}

#endif
