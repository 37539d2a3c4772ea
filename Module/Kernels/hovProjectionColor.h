/**
 * @file hovProjectionColor.h
 * @brief Per-vertex quantities of the OpenGL cell projection (HIAC section 7):
 * the colour of a region vertex by methods M0-M3, the table of method M2, and
 * the opacity texture M(u, v) = 1 - exp(-u v).
 *
 * A region vertex of a projected convex cell (or transfer-function slab) is a
 * ray segment of length L (dataset units) from a front point to a back point,
 * on which extinction tau and colour vary linearly (hovSegmentIntegral.h).
 * The rasteriser interpolates u = L and v = tau_avg = (tauFront + tauBack)/2
 * over the region (both are linear there for a parallel projection), looks up
 * the opacity A = M(u, v) = 1 - exp(-u v) per fragment and blends
 * (A k, A) with premultiplied "over".
 *
 * Colour per vertex, Williams-Max emission (k = an effective chromaticity):
 *  - M0 (InterpolatedOpacity): k = (kFront + kBack)/2 and the opacity itself
 *    interpolated from the vertices, no texture (Shirley-Tuchman);
 *  - M1 (AverageColor): k = (kFront + kBack)/2;
 *  - M2 (TableColor): k = (1 - beta) kFront + beta kBack with the back weight
 *    beta = WBack / A of eq. 8 looked up bilinearly in a SegmentColorTable
 *    over the optical depths (tauFront L, tauBack L); outside its range M1;
 *  - M3 (ExactColor): k = C / A with C, A from hov::IntegrateSegment (the
 *    kernel the CPU path uses, never a separate formula).
 * Wilhelms-Van Gelder emission (glow g not proportional to extinction, so
 * C/A is unbounded where nothing absorbs): the vertex carries the effective
 * glow g_eff = C / (L phi(D)), phi(D) = (1 - e^-D)/D, D = L tau_avg, and the
 * fragment's radiance is g_eff L phi(D) = g_eff A / tau_avg (exact for
 * constant glow and extinction): M0/M1 g_eff = (gFront + gBack)/2; M2 C from
 * the table's VFront, VBack; M3 C from hov::IntegrateSegment.
 *
 * Opacity texture (OpacityTexture*): a Size x Size float texture of
 * M(u, v) = 1 - exp(-u v) on the nodes u, v = i UMax / (Size - 1) (HIAC
 * section 7's table, u a length and v an extinction in reciprocal units).
 * M depends on the product u v only, so any (L / c, tau_avg c), c > 0, gives
 * the exact opacity; the lookup takes c = sqrt(L / tau_avg), i.e. the point
 * u = v = sqrt(L tau_avg) on the diagonal: no scale to choose, no clamping
 * artefact for thick or dense cells, and one square root (no logarithm) per
 * fragment. Beyond u = UMax the opacity is 1 (1 - exp(-36) = 1 - 2.3e-16).
 * The texture unit's bilinear filter there is exact for thin segments (u v
 * is bilinear) and within h^2 / (4e) = 1.3e-5 of the exact opacity in
 * general (h = UMax / (Size - 1); TestProjectionColor measures it).
 * OpacityFromTexture is the reference of the lookup the fragment shader
 * performs (hovProjectionFS.glsl, hovOpacityFromTexture: the same
 * point, the texture unit's GL_LINEAR filter).
 *
 * Thread safety: all functions are re-entrant; a SegmentColorTable is
 * read-only after construction.
 * @sa hovSegmentIntegral.h, hov::ProjectionRegions
 */
#ifndef hovProjectionColor_h
#define hovProjectionColor_h

#include "hovConfig.h"
#include "hovSegmentIntegral.h" // SegmentEnd, EmissionModel

#include <vector> // table storage

namespace hov
{
class TransferFunction;
/// HIAC section 7's colour methods, in increasing order of accuracy.
enum class ProjectionColorMethod
{
  InterpolatedOpacity = 0, ///< M0
  AverageColor = 1,        ///< M1
  TableColor = 2,          ///< M2
  ExactColor = 3           ///< M3
};

/// What one region vertex carries (see file doc).
struct ProjectionVertexColor
{
  /// 1 - exp(-L tau_avg): for M0 (which interpolates it) and M3 (the segment
  /// kernel's A); 0 for M1 and M2 (the fragment shader computes the opacity).
  double Alpha = 0.0;
  double Color[3] = { 0.0, 0.0, 0.0 }; ///< chromaticity k (Williams-Max) or effective glow (WVG)
};

/**
 * Table of the eq. 8 weights over the optical depths a = tauFront L and
 * c = tauBack L in [0, MaxDepth]^2 (Size^2 nodes, bilinear), computed with
 * hov::ExactSegmentWeights: the back fraction WBack / A (Williams-Max) and
 * VFront, VBack (Wilhelms-Van Gelder).
 */
class HOV_EXPORT SegmentColorTable
{
public:
  static constexpr int Size = 33;
  static constexpr double MaxDepth = 8.0;
  SegmentColorTable();
  /// False (outputs untouched) if a depth is outside [0, MaxDepth] or not finite.
  bool Lookup(double depthFront, double depthBack, double& backFraction, double& vFront,
    double& vBack) const;

private:
  std::vector<double> BackFraction, VFront, VBack;
};

/**
 * The vertex quantities of a segment of length @p length from @p front to
 * @p back (see file doc); @p table is used by M2 only.
 */
HOV_EXPORT ProjectionVertexColor ComputeProjectionVertex(ProjectionColorMethod method,
  EmissionModel emission, double length, const SegmentEnd& front, const SegmentEnd& back,
  const SegmentColorTable& table);

/**
 * The vertex quantities in GPU-compatible semantics, where the projection's
 * slabs follow the linear opacity (GPUAverageExtinction): @p front.Tau and
 * @p back.Tau are the opacities at the segment's ends, @p sFront, @p sBack its
 * scalars, @p extinction the refined extinction table. M0's opacity uses the
 * exact mean extinction; M3 integrates @p extinction over the segment
 * (hov::IntegrateLinearScalar, the CPU path's kernel); M1, M2 as
 * ComputeProjectionVertex with the ends' exact extinctions.
 */
HOV_EXPORT ProjectionVertexColor ComputeProjectionVertexGPU(ProjectionColorMethod method,
  EmissionModel emission, double length, const SegmentEnd& front, const SegmentEnd& back,
  double sFront, double sBack, const TransferFunction& extinction, double inverseUnit,
  const SegmentColorTable& table);

/**
 * GPU-compatible semantics without slabs: on an interval of the transfer
 * function the opacity a is linear in s, so along a segment through a convex
 * cell (s affine) a goes linearly from @p aFront to @p aBack, and the average
 * extinction (unit distance 1) is the mean of -ln(1 - a) over that range.
 * With P = 1 - min(a), Q = 1 - max(a) and x = (P - Q)/P (the antiderivative
 * of -ln p is p - p ln p):
 *   mean = -ln P + M(x),  M(x) = 1 + (1 - x) ln(1 - x) / x = sum_n x^n / (n (n + 1)),
 * both terms >= 0 (no cancellation); -ln P = -log1p(-min a) (accurate for
 * small opacities), M by its series below x = 0.1. 1 - a is clamped at
 * OpaqueClamp as in hov::TransferFunction (a = 1 at one end: the integrable
 * log singularity); a >= 1 at both ends gives +infinity (an opaque medium).
 * The OpenGL projection's fragment shader computes the same formula in float
 * (hovProjectionFS.glsl, hovGPUAverageExtinction), from the
 * opacities, which float keeps to 6e-8 relative (1 - a would lose small
 * opacities).
 */
HOV_EXPORT double GPUAverageExtinction(double aFront, double aBack);

/// Layout of the opacity texture (see file doc).
struct OpacityTexture
{
  static constexpr int Size = 512;
  static constexpr double UMax = 6.0;
  /// Size * Size texels, row j (v) after row j-1, M(u_i, v_j) at i + Size j.
  static std::vector<float> Texels();
};

/**
 * The opacity the fragment shader computes for length @p length and average
 * extinction @p tau from the texels of OpacityTexture::Texels() (same point,
 * same bilinear interpolation; in double here). 0 unless length, tau and
 * @p lengthScale are positive; the value does not depend on the scale (the
 * lookup point u = v = sqrt(L tau) is scale-free).
 */
HOV_EXPORT double OpacityFromTexture(
  const std::vector<float>& texels, double length, double tau, double lengthScale);
}

#endif
