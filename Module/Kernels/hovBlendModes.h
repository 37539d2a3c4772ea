/**
 * @file hovBlendModes.h
 * @brief Exact maximum, minimum and average intensity projections (VTK's
 * blend modes MAXIMUM_INTENSITY, MINIMUM_INTENSITY, AVERAGE_INTENSITY)
 * along a ray, for linear segments and polynomial pieces of the field.
 *
 * What VTK 9.1's GPU ray caster computes (vtkVolumeShaderComposer.h,
 * ShadingDeclarationFragment / ShadingSingleInput / ShadingExit; the opacity
 * table in vtkOpenGLVolumeOpacityTable.cxx), in the continuum limit of its
 * samples, for one scalar component:
 *  - MIP:  smax = max of s over the ray; pixel (premultiplied)
 *          RGBA = (c(smax) a(smax), a(smax)), c the colour function, a the
 *          RAW scalar-opacity function (no unit-distance correction: the
 *          table is corrected only for COMPOSITE and ADDITIVE), both clamped
 *          to [0, 1]. MinIP: the same with smin. No shading in either.
 *  - AVERAGE: v = (int_I a(s) sn dt) / |I|, I = {t on the ray: lo <= s(t)
 *          <= hi} ([lo, hi] = vtkVolumeMapper::AverageIPScalarRange, swapped
 *          if reversed; default [VTK_FLOAT_MIN, VTK_FLOAT_MAX] = +-1e38),
 *          sn = (s - r0)/(r1 - r0) the scalar normalised by the DATA scalar
 *          range [r0, r1] (the volume texture's range); pixel
 *          RGBA = (clamp(v), clamp(v), clamp(v), 1): grey and OPAQUE, no
 *          colour function; transparent (the GPU discards) if |I| = 0.
 * The GPU's sample mean over equispaced samples becomes the length-weighted
 * mean over I.
 *
 * Per ray, a RayBlendState accumulates, in any order (max, min and sums
 * commute, so no visibility sort is needed), over segments of POSITIVE
 * length (a grazing point of measure zero contributes nothing, as for the
 * GPU's samples):
 *  - the extremum of s and where it is (front-most t on ties);
 *  - int_I a(s) sn dt and |I| (average intensity, VTK's definition);
 *  - int s dt and the length (the plain mean of the field, MeanScalar).
 * ResolveBlend turns the state into the pixel as above.
 *
 * Linear segments (linear cells; s affine in t): the extremes are the end
 * values (exact); I is an interval found by one division per limit; on each
 * transfer-function interval inside I, a(s) sn(s) is a quadratic in t,
 * integrated by Simpson's rule (exact for quadratics).
 *
 * Polynomial pieces S(tau), tau in [0, h], degree <= 8 (higher-order cells,
 * hovCellRestriction.h; ErrorBound e_r = |s - S| from the restriction):
 *  - extremum (PolynomialExtremum): candidates tau = 0, h and the roots of
 *    S' in [0, h] (FindRoots, hovPolynomial.h); each candidate evaluated by
 *    compensated Horner with its bound e_i. For an interior candidate r^ the
 *    true critical point r is bracketed by checking that S' changes sign
 *    (beyond its evaluation bound) on [r^ - d, r^ + d], d doubled from
 *    16 eps max(h, |r^|) up to h; then |S(r) - S(r^)| <= M2 d^2 / 2 with
 *    M2 = sum_k k (k-1) |c_k| h^(k-2) >= max |S''|. The returned bound is
 *        ErrorBound = e_r + max_i (e_i + M2 d_i^2 / 2),
 *    rigorous provided FindRoots isolates every sign change of S' (its
 *    documented guarantee); a candidate whose bracket cannot be verified (a
 *    root of S' of even multiplicity: not an extremum) uses d = h / 2^10.
 *    Measured (TestBlendModes): true error <= 2.2e-16 relative to the field
 *    scale for degrees 2..8, bound/true typically 1e0..1e2.
 *  - average: [0, h] is split at every root of S = lo, S = hi and S = X_k
 *    for the table nodes X_k inside the piece's range; on each sub-interval
 *    a(S) sn(S) is a polynomial of degree <= 2 deg S <= 16, integrated by
 *    the 15-point Kronrod rule (exact to degree 22: rounding only). The
 *    restriction error adds at most h e_r (max|a'| + max|a| / (r1 - r0)) to
 *    the integral, plus max(a sn) times the shift e_r / |S'| of each range
 *    limit crossing.
 *  - plain integral: the same Kronrod rule on S (exact).
 *
 * Degenerate input: segments with length <= 0 or not finite, non-finite
 * scalars or coefficients are skipped and counted (SkippedSegments); r1 <= r0
 * gives sn = 0; the results are never NaN or infinite for finite input.
 *
 * Transfer function: ResolveBlend and the average read the RAW opacity a(s)
 * and colour c(s) from a hov::TransferFunction built with
 * BlendModeTableSpec(spec) (the same nodes, VTKUnstructured semantics, unit
 * distance 1, so its Tau IS a(s); jumps take the right limit at their node).
 *
 * Thread safety: stateless functions, re-entrant; the table is read only;
 * a RayBlendState belongs to one ray (MergeBlendStates combines partial
 * states, e.g. from tiles or threads).
 * @sa hovTransferFunction.h, hovPolynomial.h, hovCellRestriction.h
 */
#ifndef hovBlendModes_h
#define hovBlendModes_h

#include "hovCompositing.h"
#include "hovConfig.h"
#include "hovPolynomial.h"
#include "hovTransferFunction.h" // TransferFunctionSpec, the raw table

namespace hov
{
/// VTK's blend modes we support; the values are vtkVolumeMapper::BlendModes'.
enum class BlendMode : int
{
  Composite = 0,
  MaximumIntensity = 1,
  MinimumIntensity = 2,
  AverageIntensity = 3
};

/// VTK_FLOAT_MAX (vtkType.h): the default |limit| of AverageIPScalarRange.
constexpr double VTKFloatMax = 1.0e+38;

struct BlendSettings
{
  BlendMode Mode = BlendMode::MaximumIntensity;
  /// vtkVolumeMapper::AverageIPScalarRange (swapped if reversed).
  double AverageRange[2] = { -VTKFloatMax, VTKFloatMax };
  /// The data scalar range [r0, r1] that normalises s for the average.
  double ScalarRange[2] = { 0.0, 1.0 };
};

/// What one ray has accumulated (see file doc).
struct RayBlendState
{
  bool Found = false;       ///< some segment of positive length was seen
  double Value = 0.0;       ///< max (MIP) or min (MinIP) of s
  double T = 0.0;           ///< ray parameter where Value is attained (front-most)
  double ErrorBound = 0.0;  ///< |Value - true extremum| <= ErrorBound (0 on linear segments)
  double WeightedIntegral = 0.0; ///< int_I a(s) sn(s) dt (average mode only)
  double InRangeLength = 0.0;    ///< |I| (average mode only)
  double ScalarIntegral = 0.0;   ///< int s dt over every segment
  double Length = 0.0;           ///< total length of the segments
  int Segments = 0;
  int SkippedSegments = 0;  ///< degenerate or non-finite input (file doc)
};

/// The spec of the raw table read by the blend modes (see file doc).
HOV_EXPORT TransferFunctionSpec BlendModeTableSpec(const TransferFunctionSpec& spec);

/**
 * Extremum of S(tau) on [0, @p h] (file doc): @p sign = +1 for the maximum,
 * -1 for the minimum. @p value, @p where (tau, front-most on ties) and
 * @p bound (without the restriction error). False for invalid input.
 */
HOV_EXPORT bool PolynomialExtremum(
  const Polynomial& s, double h, int sign, double& value, double& where, double& bound);

/// A segment of length @p length starting at ray parameter @p tFront on which
/// s goes linearly from @p sFront to @p sBack.
HOV_EXPORT void AccumulateLinearSegment(RayBlendState& state, const BlendSettings& settings,
  const TransferFunction& table, double tFront, double length, double sFront, double sBack);

/**
 * A polynomial piece: s(tStart + tau) = S(tau) +- @p errorBound for tau in
 * [0, @p length] (a RestrictedPiece: tStart = T0, length = T1 - T0).
 */
HOV_EXPORT void AccumulatePolynomialSegment(RayBlendState& state, const BlendSettings& settings,
  const TransferFunction& table, double tStart, double length, const Polynomial& s,
  double errorBound = 0.0);

/// Combine the partial state @p other of the same ray into @p into.
HOV_EXPORT void MergeBlendStates(
  RayBlendState& into, const RayBlendState& other, const BlendSettings& settings);

/// The pixel (premultiplied RGBA) of a finished ray, as VTK's GPU mapper
/// defines it for settings.Mode (file doc); transparent if nothing was seen.
HOV_EXPORT RGBA ResolveBlend(
  const RayBlendState& state, const BlendSettings& settings, const TransferFunction& table);

/// The plain length-weighted mean of s over the ray (0 if nothing was seen).
HOV_EXPORT double MeanScalar(const RayBlendState& state);
}

#endif
