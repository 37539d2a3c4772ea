/**
 * @file hovOpacityRefinement.h
 * @brief Piecewise-linear extinction for GPU-compatible opacity semantics.
 *
 * vtkGPUVolumeRayCastMapper converges to the extinction tau(s) = -ln(1 -
 * a(s)) / u, which is convex in s where the opacity a(s) is linear. The exact
 * segment integral needs tau linear between breakpoints, so every opacity
 * interval is split until the chord of tau has relative error <= tol:
 *   |tau_chord(s) - tau(s)| <= tol tau(s)   everywhere.
 * With extinction within a factor (1 +- tol) along a whole ray, its opacity is
 * off by at most tol/e and its Williams-Max colour by at most 2 tol max|c|.
 *
 * Refinement is global and greedy: the piece with the largest error is
 * bisected first, so a node budget, if reached, leaves the error balanced.
 * The relative error of a piece is taken analytically at a zero end (chord
 * slope over tau'(0) = 1/u) and on 33 samples inside (the error is smooth
 * there). Opacity near 1 is handled through p = 1 - a carried exactly
 * (midpoints of p, never 1 - a recomputed), and p is clamped at OpaqueClamp:
 * an opacity reaching exactly 1 at one end of an interval is an integrable
 * log singularity and is capped at tau = -ln(OpaqueClamp)/u = 27.6/u.
 *
 * Thread safety: re-entrant.
 * @sa hovTransferFunction.h
 */
#ifndef hovOpacityRefinement_h
#define hovOpacityRefinement_h

#include "hovConfig.h"

#include <utility> // std::pair
#include <vector>  // nodes

namespace hov
{
/// 1 - a is never taken below this (tau <= 27.6/u).
constexpr double OpaqueClamp = 1e-12;

/// GPU-compatible extinction for opacity a with p = 1 - a known accurately.
HOV_EXPORT double GPUExtinction(double a, double p, double invUnit);

/// One opacity interval [S0, S1] with opacity linear from A0 to A1 (both < 1 or one = 1).
struct OpacityInterval
{
  double S0, A0, S1, A1;
};

struct RefinementResult
{
  /// Per interval: interior nodes (s, tau), increasing in s.
  std::vector<std::vector<std::pair<double, double>>> Interior;
  int Added = 0;          ///< interior nodes in all
  double WorstError = 0;  ///< largest relative chord error left
  bool Exhausted = false; ///< the budget was reached before the tolerance
};

/**
 * Refine every interval jointly until the relative chord error of tau is at
 * most @p tol, adding at most @p budget nodes.
 */
HOV_EXPORT RefinementResult RefineGPUExtinction(
  const std::vector<OpacityInterval>& intervals, double unit, double tol, int budget);
}

#endif
