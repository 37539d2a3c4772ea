/**
 * @file hovCellRestriction.h
 * @brief A cell's interpolated scalar restricted to a ray segment, as
 * polynomial pieces ready for IntegratePolynomialScalar
 * (hovPolynomialSegment.h).
 *
 * Input: a cell (hovCellShapes.h: VTK node order, straight edges, geometry
 * from the corners), its node scalars, the ray x(t) = o + t d and an inside
 * interval [t0, t1] (hovRayCell.h). Output: pieces (T0, T1, S, ErrorBound)
 * covering [t0, t1] in order, S a polynomial in the LOCAL variable
 * tau = t - T0, tau in [0, T1 - T0] (the segment variable of
 * IntegratePolynomialScalar), with |s(T0 + tau) - S(tau)| <= ErrorBound.
 *
 * Affine geometry (IsGeometryAffine: tetrahedra; voxels; parallelepiped
 * hexahedra; wedges whose top is a translate of the bottom; relative
 * tolerance AffineTolerance of the cell extent): pc(tau) = pc(T0) +
 * tau A d is affine, so s is EXACTLY a polynomial (linear tet 1, quadratic
 * tet 2, linear wedge 2, trilinear hex 3, quadratic wedge 3, quadratic hex
 * 4, triquadratic hex 6) whose coefficients come from direct expansion of
 * the shape functions along the line (CellShapeFunctionsAlongLine). One
 * piece; ErrorBound is a rounding estimate 32 eps (sum_i |s_i|) (measured
 * errors ~1e-15 relative to the scalar range, TestCellRestriction).
 *
 * General geometry (distorted hexahedra, general wedges, every pyramid: the
 * collapsed map makes s rational in t near the apex): pc(t) by InvertGeometry
 * (Newton, step < 1e-14, warm-started from the neighbouring sample) at the
 * N + 1 = 17 Chebyshev extreme points of [T0, T1]; s there; the Chebyshev
 * coefficients c_0..c_16 of the degree-16 interpolant (DCT-I). The returned
 * S is the truncation to the smallest degree m <= 8 with
 *   ErrorBound = 2 sum_{k > m} |c_k| + 64 eps sum |c_k| + NewtonFloor
 * below the tolerance (the factor 2 covers the interpolant's own error
 * |s - p_16|, which for the geometric coefficient decay of analytic s is
 * below sum_{k>16} |a_k| ~ |c_16|; NewtonFloor = 1e-13 x scalar scale covers
 * the Newton tolerance). If ErrorBound > RelativeTolerance x (scalar range
 * of the nodes, or max |s_i| if that is 0), the interval is bisected
 * (depth-first, at most MaxPieces pieces; beyond, Converged = false and
 * the pieces are returned with their bounds). S is converted from the
 * Chebyshev basis in x in [-1, 1] to monomials in x (|coefficients| grow
 * at most 2^(m-1)) and then to tau (ComposeAffine, long double).
 * Measured (TestCellRestriction, GCC 12 Release, random cells of every
 * type): affine path max error 5.5e-15 of the scalar range (triquadratic
 * hexahedron); non-affine path (corners perturbed by 0.2 of the size) max
 * error 5.0e-11 of the range at the default tolerance, actual/bound <= 0.50
 * and bound/max(actual, 1e-13 range) <= 2.9 (the test requires <= 1e3),
 * <= 13 pieces per chord (pyramids; 11 on a chord ending 1e-3 below the
 * apex).
 *
 * Domain: finite points and scalars, d != 0, t0 <= t1 finite, the ray inside
 * the cell on [t0, t1] (outside, Newton may fail: NewtonFailures counts it;
 * the sample is then taken at the best iterate).
 *
 * Thread safety: re-entrant (no shared state); the output vector is the
 * only allocation.
 * @sa hovCellShapes.h, hovRayCell.h, hovPolynomialSegment.h
 */
#ifndef hovCellRestriction_h
#define hovCellRestriction_h

#include "hovCellShapes.h"
#include "hovConfig.h"
#include "hovPolynomial.h"

#include <vector> // output pieces

namespace hov
{
/// Relative (to the cell extent) deviation from affine below which the geometry is affine.
constexpr double AffineTolerance = 1e-12;

struct CellRestrictionSettings
{
  /// Target of ErrorBound relative to the node scalars' range.
  double RelativeTolerance = 1e-10;
  /// Pieces allowed per interval (non-affine path).
  int MaxPieces = 64;
};

/// One polynomial piece of s along the ray (S in tau = t - T0).
struct RestrictedPiece
{
  double T0 = 0.0;
  double T1 = 0.0;
  Polynomial S;
  double ErrorBound = 0.0;
};

struct CellRestrictionStatus
{
  bool Affine = false;    ///< exact path taken
  bool Converged = true;  ///< every piece meets the tolerance
  int NewtonFailures = 0; ///< samples where InvertGeometry did not converge
};

/**
 * True if the geometry map is affine to within @p relativeTolerance times the
 * cell's extent (checked at every corner against the map's linearisation at
 * the centre; pyramids never are).
 */
HOV_EXPORT bool IsGeometryAffine(
  CellShape shape, const double* points, double relativeTolerance = AffineTolerance);

/// Coefficients of a field of degree <= 2 in each parametric coordinate:
/// index 9 i + 3 j + k holds the coefficient of r^i s^j t^k.
constexpr int AffineFieldTerms = 27;

/**
 * The shape functions of @p shape in that monomial basis: @p basis[27 n + m]
 * is coefficient m of node n's shape function (n < CellNodeCount). Exact for
 * every supported shape except pyramids (their shape functions are rational):
 * the coefficients are small integers, recovered from the shape functions at
 * the dyadic points {0, 1/2, 1}^3 by integer transforms. False for pyramids.
 * @p basis must hold 27 MaxCellNodes values.
 */
HOV_EXPORT bool AffineFieldBasis(CellShape shape, double* basis);

/**
 * Per-cell set-up of RestrictAffineField: @p c[m] = sum_n scalars[n]
 * basis[27 n + m] (the interpolated field as a polynomial in the parametric
 * coordinates; rounding <= NodeCount eps sum |basis| |s_n|).
 */
HOV_EXPORT void AffineFieldCoefficients(
  const double* basis, int nodeCount, const double* scalars, double c[AffineFieldTerms]);

/**
 * The field c (AffineFieldCoefficients) along the parametric line
 * pc(tau) = @p start + tau @p step as one polynomial in tau (degree <= 6):
 * the same polynomial as the expansion of the shape functions along the line
 * (CellShapeFunctionsAlongLine) weighted by the scalars, up to rounding, at a
 * fraction of the cost. The affine cells' per-pixel restriction. Fields of
 * total degree <= 2 (tetrahedra, linear wedges: every coefficient of
 * i + j + k > 2 exactly 0) take the quadratic form directly
 * (s(a), s'(a) . b, b^T H b: ~50 flops).
 */
HOV_EXPORT Polynomial RestrictAffineField(
  const double c[AffineFieldTerms], const double start[3], const double step[3]);

/**
 * The restriction of the cell's scalar to [@p t0, @p t1] (see file doc);
 * @p out is cleared first. Returns the number of pieces (0 for invalid input).
 */
HOV_EXPORT int RestrictCellScalar(CellShape shape, const double* points, const double* scalars,
  const double origin[3], const double direction[3], double t0, double t1,
  const CellRestrictionSettings& settings, std::vector<RestrictedPiece>& out,
  CellRestrictionStatus* status = nullptr);
/// inv = J^-1 of a row-major 3x3 matrix (cofactors); false if singular or
/// not finite. Shared by the restriction and hovFieldGradient.
HOV_EXPORT bool InvertMatrix3(const double j[9], double inv[9]);
}

#endif
