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
 * finite) it is recomputed exactly in rational arithmetic. Non-finite inputs
 * give 0.
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
