/**
 * @file hovGradientRestriction.h
 * @brief The gradient of a cell's interpolated scalar restricted to a ray
 * segment, as polynomial pieces: the input of hov::IntegrateShadedPolynomial
 * (hovShadedSegment.h) for cells whose gradient is not a polynomial along
 * rays (distorted hexahedra, general wedges, pyramids), so that shading and
 * gradient opacity cost one Newton inversion per fitted point instead of one
 * per quadrature sample.
 *
 * Convention (hovFieldGradient.h): grad s = J^-T ds/dpc in the caller's
 * (dataset) coordinates, the gradient of s - s_0 (a constant field has the
 * zero gradient exactly). Output: pieces (T0, T1, G[3], ErrorBound) covering
 * [t0, t1] in order, each component a polynomial in tau = t - T0, with
 * ErrorBound an estimate of |grad s(T0 + tau)_i - G_i(tau)| (the scalar's
 * rule, hovCellRestriction.h: reliable for the geometric decay of the
 * coefficients of analytic functions, not a proof).
 *
 * Method: as hovCellRestriction.h's non-affine path, per component
 * (hovChebyshevFit.h): CellFieldAndGradient at the 17 Chebyshev extreme
 * points (Newton warm-started from the previous point), the degree-16
 * interpolant, truncated to the smallest degree <= 8 whose bound
 * 2 sum_{k > m} |c_k| + 64 eps sum |c_k| + NewtonFloor x Scale is at most
 * RelativeTolerance x Scale; the worst component decides. Scale is the
 * largest sum |c_k| of a component's interpolant on the whole interval
 * [t0, t1]: at least the largest sampled component and at most 32 times it
 * (a constant field: Scale 0, the exact zero piece). An interval whose bound
 * is larger is bisected (at most MaxPieces pieces; beyond, Converged = false
 * and the pieces are returned with their bounds).
 *
 * What that means for shading: the normal's direction is off by about
 * sqrt(3) ErrorBound / |grad s| radians, so where |grad s| is within a
 * factor 10-30 of Scale the shaded colour moves by ~1e-9 per unit of
 * emission at the default 1e-10, the size of the quadrature's own tolerance
 * and far below a float image's rounding; where |grad s| is much smaller the
 * normal is known less well, over a stretch of the ray proportional to
 * |grad s|. The shaded segments do not add this to their error estimate.
 * Callers that need more take the pointwise route (CellFieldAndGradient per
 * sample).
 *
 * Domain: as RestrictCellScalar (finite input, the ray inside the cell on
 * [t0, t1]; Newton failures are counted in NewtonFailures and the sample is
 * taken at the best iterate). Pyramids: the gradient is bounded but not
 * smooth at the apex, so chords through it may not converge.
 *
 * Thread safety: re-entrant; the output vector is the only allocation
 * (hovFieldGradient.h's basis table aside).
 * @sa hovCellRestriction.h, hovFieldGradient.h, hovChebyshevFit.h
 */
#ifndef hovGradientRestriction_h
#define hovGradientRestriction_h

#include "hovCellRestriction.h" // CellRestrictionSettings, CellRestrictionStatus
#include "hovCellShapes.h"
#include "hovConfig.h"
#include "hovPolynomial.h"

#include <vector> // output pieces

namespace hov
{
/// One polynomial piece of grad s along the ray (G in tau = t - T0).
struct GradientPiece
{
  double T0 = 0.0;
  double T1 = 0.0;
  Polynomial G[3];
  double ErrorBound = 0.0; ///< per component
};

/**
 * The restriction of grad s to [@p t0, @p t1] (file doc); @p out is cleared
 * first. Returns the number of pieces (0 for invalid input).
 */
HOV_EXPORT int RestrictCellGradient(CellShape shape, const double* points, const double* scalars,
  const double origin[3], const double direction[3], double t0, double t1,
  const CellRestrictionSettings& settings, std::vector<GradientPiece>& out,
  CellRestrictionStatus* status = nullptr);
}

#endif
