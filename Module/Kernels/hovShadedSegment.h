/**
 * @file hovShadedSegment.h
 * @brief Emission-absorption integral over a ray segment whose colour is
 * shaded with a VARYING gradient (higher-order cells, positional lights) and
 * whose extinction is modulated by the gradient opacity: adaptive spectral
 * quadrature with an error estimate.
 *
 * Domain: t in [0, L] from the segment's front (eye side); the field s(t)
 * and its world gradient g(t) from a sampler; the table of
 * hovTransferFunction.h. With gamma(t) = GO(|g(t)|) (hovGradientOpacity.h)
 * and c_sh(t) = the shaded chromaticity (ComputeShadingTransform at the point
 * o + t d, hovVolumeShading.h):
 *     tau_e(t) = gamma(t) tau(s(t)),  D(t) = int_0^t tau_e,
 *     C = int_0^L E(t) e^-D(t) dt,    A = 1 - e^-D(L),
 * E = c_sh tau_e (Williams-Max) or EmissionFactor c_sh (Wilhelms-Van Gelder).
 * Neither tau_e nor c_sh is polynomial (|g| and the normalisation are
 * square roots, the clamp and GO have kinks), so no closed form exists.
 *
 * Quadrature: [0, L] is cut at the caller's breakpoints (where the
 * integrand has kinks or jumps: transfer-function node crossings of s, GO
 * kinks), then each piece is covered by panels processed front to back. On
 * a panel [a, b] the integrand is sampled at the N + 1 = 17 Chebyshev-Lobatto
 * points; tau_e's Chebyshev interpolant (DCT-I) is integrated exactly
 * (indefinite integral in the Chebyshev basis, Clenshaw-Curtis style) to give
 * D at the same points, then E e^-D is integrated by Clenshaw-Curtis. Error
 * estimates from the last three Chebyshev coefficients (tail):
 *     eD = (b - a) tail(tau_e),
 *     eC = (b - a) tail(E e^-D) + eD (|C_panel| + R),
 * R bounding what lies behind (WM: max(1, max c); WVG: EF max(1, max c)
 * (L - b) + 1). A panel is accepted if T_front eC <= Tolerance (b - a)/L,
 * or if every tail is within the rounding floor 16 eps of the (finite) sum
 * of its function's |coefficients| (bisection cannot go below rounding: colours far
 * beyond [0, 1], e.g. 1e300, would otherwise spend the panel budget at the
 * front and leave the rest coarse; Converged = false if the target was
 * missed), else bisected (depth <= MaxDepth, panels <= MaxPanels; beyond:
 * accepted, Converged = false). The sum of accepted T_front eC is ErrorEstimate. A
 * panel whose integrand is a polynomial of degree <= 13 is integrated exactly
 * (tail 0 up to rounding); for analytic integrands the error decays like
 * rho^-N per panel and halving a panel multiplies it by ~2^-16.
 * Integration stops when the transmittance drops below
 * 1e-3 Tolerance / R (the rest is added to ErrorEstimate).
 *
 * Mergeable breakpoints (optional, one flag each): where the integrand is
 * known to hide nothing narrow (TransferFunction::IsSmoothNode(): tau convex
 * and the colour linear across the node; extrema of s are never mergeable, so
 * s is monotone in every piece and tau, convex in s, peaks at a piece's ends,
 * which are sampled). When there are more than P = MaxPieces (default and
 * at most MaxPanels / 2) pieces, evenly spaced ones of the mergeable
 * breakpoints are stepped over (SkippedBreakpoints) so that at most P pieces
 * remain, or all of them are if the others alone are that many; every other
 * breakpoint is kept. IntegrateShadedPolynomial leaves the stepped-over
 * crossings out before locating them (ShadedBreakpoints). A table refined to a tight
 * GPU-compatible tolerance (up to 16,384 nodes, nearly all added inside the
 * user's intervals) then costs panels for its shape, not one per node; an
 * opaque interval, a jump or a narrow band of the user's function is always
 * cut out exactly. Without flags (nullptr) every breakpoint is kept.
 *
 * A piece whose midpoint has infinite extinction (an opaque table interval,
 * GPU-compatible a = 1) absorbs everything: C += T c_sh(front) (WM), A = 1.
 * A non-finite sample inside a finite piece (missing breakpoints, a failed
 * Newton inversion in the sampler) is taken as transparent and clears
 * Converged.
 *
 * IntegrateShadedPolynomial (affine cells: s and g polynomials in t):
 * breakpoints at every table-node crossing of s (monotone runs between the
 * roots of s', SolveMonotone; but the mergeable ones stepped over are left
 * out before they are located: ShadedBreakpoints with MaxPieces), the
 * extrema of s, and, when |g|^2 has degree <= 9, every
 * crossing of a GO kink (FindRoots on |g|^2 = m^2); shading clamp kinks are
 * left to the adaptivity. If s is linear, g constant, every light directional
 * (and GO, shading then constant), it returns the exact closed form
 * IntegrateLinearScalarShaded instead (ExactPath = true).
 *
 * Measured (TestShadedSegment, GCC 12 Release) against a composite
 * Gauss-Legendre reference on quadratic fields: requested 1e-6 -> error
 * 1.8e-8 (550 panels), 1e-9 -> 1.6e-13, 1e-12 -> 2.3e-16; the estimate was
 * never exceeded (worst error/estimate 0.83). Positional lights with
 * attenuation and spot cones (TestShadedSegmentLights, 30 cases, 1e-9
 * requested): error 3.8e-14, error/estimate 0.52. See the tests' [measured]
 * lines.
 *
 * Thread safety: re-entrant (table and GO function read only; the sampler
 * must be); IntegrateShadedSegment does not allocate, IntegrateShadedPolynomial
 * allocates its breakpoint list.
 * @sa hovVolumeShading.h, hovGradientOpacity.h, hovFieldGradient.h, hovPolynomialSegment.h
 */
#ifndef hovShadedSegment_h
#define hovShadedSegment_h

#include "hovCompositing.h"
#include "hovConfig.h"
#include "hovPolynomial.h"
#include "hovSegmentIntegral.h" // EmissionModel
#include "hovVolumeShading.h"   // VolumeShadingSettings

#include <vector> // ShadedBreakpoints output

namespace hov
{
class GradientOpacityFunction;
class TransferFunction;

/// s(t) and its world gradient at ray parameter t (segment-local, t in [0, L]).
using FieldGradientSampler = void (*)(void* user, double t, double& value, double gradient[3]);

/// The segment's position in the lighting frame: point(t) = Origin + t Direction
/// (Direction unit, pointing away from the eye; the view vector is -Direction).
struct SegmentRay
{
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double Direction[3] = { 0.0, 0.0, 1.0 };
};

struct ShadedSegmentSettings
{
  EmissionModel Emission = EmissionModel::WilliamsMax;
  double Tolerance = 1e-9; ///< absolute per channel of the premultiplied RGBA
  int MaxPanels = 4096;
  int MaxDepth = 40;
  /// Pieces left when mergeable breakpoints are stepped over (file doc); at
  /// most MaxPanels / 2, which is also the default (0).
  int MaxPieces = 0;
  /// Stop at the first panel that misses its budget, or once MaxPanels
  /// panels have been evaluated, accepted or bisected (Converged false, the
  /// colour incomplete): for a caller that then takes another route.
  bool StopWhenUnconverged = false;
};

struct ShadedSegmentResult
{
  RGBA Color;
  double ErrorEstimate = 0.0;
  int Panels = 0;     ///< accepted panels
  int Samples = 0;    ///< sampler calls
  int SkippedBreakpoints = 0; ///< mergeable breakpoints stepped over (file doc)
  bool Converged = true;
  bool ExactPath = false; ///< the closed form was used (IntegrateShadedPolynomial)
};

/**
 * The integral over [0, @p length] (file doc). @p breakpoints: sorted
 * positions in (0, length) where the integrand has kinks or jumps (may be
 * null); @p gradientOpacity may be null (gamma = 1).
 */
HOV_EXPORT ShadedSegmentResult IntegrateShadedSegment(const TransferFunction& tf,
  FieldGradientSampler sampler, void* user, double length, const double* breakpoints,
  int breakpointCount, const VolumeShadingSettings& shading,
  const GradientOpacityFunction* gradientOpacity, const SegmentRay& ray,
  const ShadedSegmentSettings& settings, const unsigned char* mergeable = nullptr);

/**
 * The breakpoints IntegrateShadedPolynomial uses (file doc), sorted, in
 * (0, @p length), into @p out; with @p mergeable, one flag per breakpoint: 1
 * for a crossing of a TransferFunction::IsSmoothNode() node, 0 for other
 * nodes, the extrema of s and gradient-opacity kinks (a breakpoint found
 * twice: 1 only if both). With @p mergeable and @p maxPieces > 0, the
 * mergeable crossings IntegrateShadedSegment would step over for at most
 * @p maxPieces pieces (see MaxPieces) are left out before they are located
 * (their count in @p skipped): a table of thousands of nodes costs no root
 * finding for them.
 */
HOV_EXPORT int ShadedBreakpoints(const TransferFunction& tf, const Polynomial& s,
  const Polynomial gradient[3], const GradientOpacityFunction* gradientOpacity, double length,
  std::vector<double>& out, std::vector<unsigned char>* mergeable = nullptr, int maxPieces = 0,
  int* skipped = nullptr);

/// The integral for s(t) and grad s(t) given as polynomials in t (file doc).
HOV_EXPORT ShadedSegmentResult IntegrateShadedPolynomial(const TransferFunction& tf,
  const Polynomial& s, const Polynomial gradient[3], double length,
  const VolumeShadingSettings& shading, const GradientOpacityFunction* gradientOpacity,
  const SegmentRay& ray, const ShadedSegmentSettings& settings);
}

#endif
