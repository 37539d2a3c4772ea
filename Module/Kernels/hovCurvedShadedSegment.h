/**
 * @file hovCurvedShadedSegment.h
 * @brief The RAY_CAST segment integral with the volume's own shading and
 * gradient opacity (hovVolumeShading.h, hovGradientOpacity.h) through a
 * Lagrange cell of any order, straight-sided or curved.
 *
 * On the interval [t0, t1] of the ray o + t d inside the cell:
 *  - linear field along the ray (an affine cell of line degree 1: linear
 *    tetrahedra) under directional lights: the gradient is constant, so the
 *    shading transform and the gradient-opacity factor are constant and the
 *    integral is the closed form IntegrateLinearScalarShaded (exact,
 *    ErrorEstimate 0);
 *  - otherwise: IntegrateShadedSegment (hovShadedSegment.h: adaptive
 *    Chebyshev quadrature with an error estimate) with the exact field and
 *    world gradient at each sample (Newton inversion of the geometry from the
 *    previous sample, InvertLagrangeGeometry; grad s = J^-T df/dpc), cut at
 *    the transfer-function node crossings located on the field representation
 *    of IntegrateCurvedSegment (RepresentFieldOnSegment, LocateBreakpoints).
 * The estimate is the quadrature's (the field is sampled exactly, to the
 * inversion's tolerance); a failed inversion clears Converged. The cost is
 * bounded: at most 128 panels of 17 samples per segment, bisection depth 16
 * (beyond: the result with its estimate, Converged false; the robustness
 * test's fields of 1e9 and more would otherwise take minutes).
 *
 * Frames: the ray, the cell and the lights in one frame (the caller's).
 *
 * Thread safety: re-entrant; the cell, table and functions are read only.
 * @sa hovCurvedSegment.h, hovShadedSegment.h, hovVolumeShading.h
 */
#ifndef hovCurvedShadedSegment_h
#define hovCurvedShadedSegment_h

#include "hovConfig.h"
#include "hovCurvedSegment.h" // CurvedSegmentSettings, CurvedSegmentResult
#include "hovLagrangeCell.h"  // LagrangeCellView

namespace hov
{
class TransferFunction;

/**
 * The shaded integral over [@p t0, @p t1] of o + t d inside @p cell
 * (@p pcGuess: parametric coordinates at t0, may be null); file doc.
 * Uses settings.Quadrature.Emission and .Tolerance, settings.Shading (null
 * or Shade off: unshaded colour) and settings.GradientOpacity (null: 1).
 */
HOV_EXPORT CurvedSegmentResult IntegrateCurvedShadedSegment(const LagrangeCellView& cell,
  const CellDerivativeBounds& bounds, const TransferFunction& tf, const double origin[3],
  const double direction[3], double t0, double t1, const double* pcGuess,
  const CurvedSegmentSettings& settings);
}

#endif
