/**
 * @file hovFieldGradient.h
 * @brief World-space gradient of a cell's interpolated scalar: constant on a
 * linear tetrahedron, polynomial along a ray in an affine cell, pointwise in
 * any straight-edged cell. The inputs of volume shading and gradient opacity
 * (hovVolumeShading.h, hovShadedSegment.h, hovGradientOpacity.h).
 *
 * Convention (VTK's GPU ray caster): the gradient points toward increasing
 * scalar, grad s = J^-T (ds/dpc), J = dx/dpc (hovCellShapes.h); lengths in
 * the caller's (dataset) coordinates.
 *
 *  - TetraGradient: grad s = (ds1 (e2 x e3) + ds2 (e3 x e1) + ds3 (e1 x e2))
 *    / (e1 . (e2 x e3)), e_i = p_i - p_0, ds_i = s_i - s_0 (exact in real
 *    arithmetic; a constant field gives exactly 0). Degenerate (zero or
 *    non-finite volume) or non-finite input: false and g = 0.
 *  - AffineGradientAlongRay: for an affine cell (IsGeometryAffine:
 *    tetrahedra, voxels, parallelepipeds, prismatic wedges; NOT pyramids)
 *    the field is a polynomial in the parametric coordinates
 *    (AffineFieldBasis) and pc is affine in t, so each component of grad s
 *    along the ray x(t) = o + t d is a polynomial in tau = t - t0 of degree
 *    (degree of s along the ray) - 1: the derivative coefficients of the
 *    27-term parametric polynomial, restricted by RestrictAffineField, then
 *    J^-T. Same base point and inverse Jacobian as RestrictCellScalar's
 *    affine path (corner 0, J at the centre), so S'(tau) = d . grad s(tau) up
 *    to rounding (TestFieldGradient: measured 2.4e-15 relative to the
 *    gradient's scale against analytic gradients, 1.6e-15 for S'). The
 *    coefficients are those of s - s_0 (node 0): a constant field has zero
 *    gradient polynomials exactly.
 *  - CellFieldAndGradient: any supported straight-edged cell at a point x:
 *    pc by InvertGeometry (warm start from @p pc), then the shape-function
 *    derivatives (exact: CellShapeDerivatives) and J^-T. The pointwise sampler for
 *    non-affine cells (distorted hexahedra, pyramids). The value and
 *    derivatives are those of s - s_0 (plus s_0): a constant field has the
 *    gradient (0, 0, 0), not rounding noise in a random direction.
 *
 * Thread safety: re-entrant, no allocation; CachedAffineFieldBasis builds its
 * table (~190 KB) once, on first use (a thread-safe function-local static).
 * @sa hovCellShapes.h, hovCellRestriction.h
 */
#ifndef hovFieldGradient_h
#define hovFieldGradient_h

#include "hovCellRestriction.h" // AffineFieldTerms
#include "hovCellShapes.h"
#include "hovConfig.h"
#include "hovPolynomial.h"

namespace hov
{
/// Gradient of the linear field on the tetrahedron @p points (4 x 3) with
/// node values @p scalars (file doc). False (g = 0) if degenerate.
HOV_EXPORT bool TetraGradient(const double* points, const double* scalars, double gradient[3]);

/**
 * grad s along x(t) = @p origin + t @p direction as three polynomials in
 * tau = t - @p t0 (file doc). False for pyramids, non-affine geometry, a
 * singular Jacobian or non-finite input (gradient untouched).
 */
HOV_EXPORT bool AffineGradientAlongRay(CellShape shape, const double* points,
  const double* scalars, const double origin[3], const double direction[3], double t0,
  Polynomial gradient[3]);

/**
 * AffineGradientAlongRay in two steps, for callers that keep a cell's inverse
 * Jacobian (hov::GeneralCells): per cell, @p coefficients[axis] = the
 * coefficients (AffineFieldTerms, hovCellRestriction.h) of d(s - s_0)/dpc_axis
 * (false for pyramids and non-finite scalars); per ray, along the parametric
 * line pc(tau) = @p start + tau @p step, the three polynomials
 * grad s = J^-T ds/dpc with @p inverseJacobian = J^-1 (row-major).
 * AffineGradientAlongRay is exactly these two calls with J at the centre.
 */
HOV_EXPORT bool AffineGradientCoefficients(
  CellShape shape, const double* scalars, double coefficients[3][AffineFieldTerms]);
HOV_EXPORT void AffineGradientAlongLine(const double coefficients[3][AffineFieldTerms],
  const double inverseJacobian[9], const double start[3], const double step[3],
  Polynomial gradient[3]);

/// AffineFieldBasis(@p shape), computed once per shape; null where there is none (pyramids).
HOV_EXPORT const double* CachedAffineFieldBasis(CellShape shape);

/**
 * The field value and world gradient at @p x inside the cell; @p pc is the
 * Newton start (in) and the parametric point found (out). False if the
 * inversion failed or the Jacobian is singular (value and gradient are then
 * taken at the best iterate, or 0 if singular), and for non-finite scalars
 * (value and gradient 0).
 */
HOV_EXPORT bool CellFieldAndGradient(CellShape shape, const double* points, const double* scalars,
  const double x[3], double pc[3], double& value, double gradient[3]);
}

#endif
