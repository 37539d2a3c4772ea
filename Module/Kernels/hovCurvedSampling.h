/**
 * @file hovCurvedSampling.h
 * @brief The fixed-sample quadratures of IntegrateCurvedSegment
 * (hovCurvedSegment.h, CurvedQuadrature): ElVis's scheme (ElVis 5.2.3:
 * trapezoid on PS segments, Gauss-Kronrod outer with trapezoid inner on S
 * segments), the fixed-step Riemann sum of ElVis's public code, and our
 * located-breakpoint rule with a fixed Gauss-Legendre node count per smooth
 * piece (exact optical depth). Internal (namespace hov::detail).
 *
 * Emission semantics as hovPolynomialSegment.h: Williams-Max colour
 * C = int c tau e^-D, Wilhelms-Van Gelder C = int g e^-D, A = 1 - e^-D(L).
 * Error estimates: ElVis PS / Riemann: |Q(h) - Q(2h)| (Q(2h) on every other
 * sample; first / second order scaled); ElVis S: sum |K15 - G7| of the outer
 * rule (the trapezoid depth's error is not estimated, as in ElVis); the
 * fixed Gauss-Legendre rule: |Q(m) - Q(m-1)| per piece.
 *
 * Thread safety: re-entrant; small heap vectors.
 * @sa hovCurvedSegment.h
 */
#ifndef hovCurvedSampling_h
#define hovCurvedSampling_h

#include "hovCurvedSegment.h"

#include <vector> // field pieces

namespace hov
{
class TransferFunction;
namespace detail
{
/**
 * ElVis or Riemann (settings.Method) over [@p t0, @p t1] on the field
 * @p pieces (ascending, covering the segment); @p smooth selects ElVis's S
 * rule; @p speed = |d|. Writes result.Color, ErrorEstimate, Samples.
 */
HOV_EXPORT void IntegrateSampledSegment(const TransferFunction& tf,
  const std::vector<FieldPiece>& pieces, bool smooth, double t0, double t1, double speed,
  const CurvedSegmentSettings& settings, CurvedSegmentResult& result);

/**
 * Our rule with @p nodes Gauss-Legendre nodes on one smooth sub-piece
 * (field @p g on ray parameters [@p a, @p b], no table node inside):
 * exact depth (tau linear in s, Bernstein antiderivative), colour by the
 * rule; composited behind result.Color; result.Samples += nodes.
 */
HOV_EXPORT void IntegrateSubPieceFixed(const TransferFunction& tf, const BernsteinPolynomial& g,
  double a, double b, double speed, int nodes, bool emission, CurvedSegmentResult& result);

/**
 * The curved branch of RepresentFieldOnSegment (Chebyshev pieces, see
 * hovCurvedSegment.h) without its affine test: for callers that already
 * know the one-piece Taylor model misses the field tolerance. Pieces are
 * bisected until their error estimate is <= @p tolerance (absolute), at most
 * @p maxPieces; @p scale is the field scale (CellDerivativeBounds::FieldScale).
 * @p pcGuess / @p pcEndGuess: the parametric coordinates at @p t0 / @p t1
 * if known (may be null). Each interior sample starts Newton from the cubic
 * Hermite interpolant (values and dpc/dt = J^-1 d) of its nearest computed
 * neighbours on both sides, sampled in bisection order.
 */
HOV_EXPORT bool RepresentCurvedField(const LagrangeCellView& cell, double scale, double tolerance,
  const double origin[3], const double direction[3], double t0, double t1, const double* pcGuess,
  int maxPieces, std::vector<FieldPiece>& out, const double* pcEndGuess = nullptr);

/// Gauss-Legendre nodes and weights on [0, 1] (@p n >= 1; Newton on P_n).
HOV_EXPORT void GaussLegendreUnit(int n, std::vector<double>& x, std::vector<double>& w);
}
}

#endif
