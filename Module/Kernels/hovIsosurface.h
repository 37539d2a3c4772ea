/**
 * @file hovIsosurface.h
 * @brief Semitransparent shaded isosurfaces embedded in the volume integral
 * of one ray segment (HIAC sections 4 and 5.2): which crossings a segment
 * owns, the premultiplied RGBA of a surface hit, and the segment integral
 * with the surfaces composited in depth order.
 *
 * Domain: a segment [0, L] of one ray, t = 0 at its front (eye side), on which
 * the isosurface field is a polynomial s(t) (hovPolynomial.h; linear in linear
 * cells). The volume may be driven by the same field (IntegrateWithSurfaces)
 * or the caller integrates the volume pieces itself (e.g. with
 * hovTwoFieldSegment.h when extinction/colour come from other arrays) using
 * the crossing list.
 *
 * Which crossings a segment owns (SurfaceCrossings) -- the rule that makes a
 * surface lying exactly on a face shared by two consecutive segments of a ray
 * count once: a segment owns the crossings with t in (0, L]; a crossing at
 * t = 0 is owned only when @p includeFront is true, which the caller sets
 * exactly where the ray ENTERS the mesh (the segment's front face is a
 * boundary face: no segment of the same ray ends there). Consecutive segments
 * A (front) and B (behind) share a point: A owns it as its back end, B does
 * not. Rounding: A and B restrict different cell polynomials to the ray, so
 * their values at the shared point differ by rounding; a root found just
 * inside both would be counted twice, one found just outside both never. To
 * make the decision from values that agree up to rounding, an end value
 * within EndSnapRelative (1e-12) * max(sum_i |c_i| L^i, |iso|) of an isovalue
 * IS a crossing at that end, and any root of that isovalue within
 * min(1e-6 L, max(16 eps L, 2 tol / |s'(end)|)) of the end is moved onto it
 * (one crossing kept). A surface within 1e-12 (relative) of a face is thus
 * drawn on the face, once, provided both cells see their value within the
 * tolerance (true when the cells agree to better than ~1e-12 relative). A
 * tangency (ray touching the surface) is one crossing (Direction 0); a
 * polynomial identically equal to the isovalue has none (HIAC 5.1: a cell
 * entirely at the contour value contributes no surface).
 *
 * Segment integral (IntegrateWithSurfaces): the volume between consecutive
 * crossings is integrated with IntegratePolynomialScalar (degree <= 1: the
 * exact linear path IntegrateLinearScalar) on s shifted to the piece
 * (ComposeAffine) -- or, three fields, with IntegrateTwoFields on the
 * extinction and colour fields shifted to the piece while the crossings come
 * from the isosurface field -- and the pieces and surfaces are composited
 * front to back:
 *   C = V[0,t1] over S1 over V[t1,t2] over S2 ... over V[tn, L].
 * Surfaces at the same t are composited by increasing isovalue index. The
 * surface RGBA comes from a caller-supplied function of the crossing (the
 * normal depends on the cell: evaluate its gradient at the crossing point and
 * call IsosurfaceHitColor); it is called lazily, front to back, and not for
 * crossings behind an opaque accumulation. With no crossing the result is
 * bitwise IntegratePolynomialScalar(tf, s, L). A surface of zero opacity only
 * splits the volume integral: pieces compose to rounding (measured 6.7e-16
 * over 160 random linear to quartic segments, also where the quadrature
 * runs); against an independent long double reference with surfaces the
 * worst error is 1.5e-16 (TestIsosurfaceSegment).
 * Error budget: each volume piece gets Tolerance * (piece length)/L divided
 * by the transmittance in front of it, so ErrorEstimate <= Tolerance as for
 * one IntegratePolynomialScalar call.
 *
 * Thread safety: re-entrant (the table is read only). SurfaceCrossings
 * allocates in its output vector; IntegrateWithSurfaces does not allocate.
 * @sa hovShading.h, hovPolynomialSegment.h, hovTwoFieldSegment.h
 */
#ifndef hovIsosurface_h
#define hovIsosurface_h

#include "hovCompositing.h"
#include "hovConfig.h"
#include "hovPolynomial.h"
#include "hovPolynomialSegment.h" // IsovalueCrossing, PolynomialSegmentSettings
#include "hovShading.h"           // ShadingLight, ShadingMaterial

#include <type_traits> // remove_reference_t (callable adaptor)
#include <vector>      // SurfaceCrossings output

namespace hov
{
class TransferFunction;

/// One user isosurface: value of the isosurface field, colour, opacity at normal incidence.
struct Isosurface
{
  double Value = 0.0;
  double Color[3] = { 1.0, 1.0, 1.0 };
  double Opacity = 1.0;
};

/// Relative tolerance of the end-of-segment rule (see file doc).
constexpr double EndSnapRelative = 1e-12;

/**
 * The crossings of the @p count isovalues that the segment [0, @p length]
 * owns (file doc), sorted by t then isovalue index, into @p out (cleared).
 * Returns their number.
 */
HOV_EXPORT int SurfaceCrossings(const Polynomial& s, double length, const double* isovalues,
  int count, bool includeFront, std::vector<IsovalueCrossing>& out);

/**
 * Premultiplied RGBA of a hit on @p surface at @p point where the field
 * gradient is @p gradient, seen along the unit vector @p toViewer (point ->
 * eye): normal by SurfaceNormal, colour by ShadePhong, opacity
 * EdgeOnOpacity(Opacity, n . v, @p minCosine). For unshaded surfaces pass a
 * material with Ambient 1, Diffuse 0, Specular 0.
 */
HOV_EXPORT RGBA IsosurfaceHitColor(const Isosurface& surface, const double point[3],
  const double gradient[3], const double toViewer[3], const ShadingLight* lights, int lightCount,
  const ShadingMaterial& material, double minCosine = DefaultEdgeOnMinCosine);

struct IsosurfaceSegmentResult
{
  RGBA Color;                 ///< premultiplied, volume and surfaces composited front to back
  double ErrorEstimate = 0.0; ///< volume quadrature error estimate (surfaces are exact)
  int Pieces = 0;             ///< volume pieces (as PolynomialSegmentResult::Pieces, summed)
  int Panels = 0;
  int Surfaces = 0;           ///< surfaces composited (those in front of full opacity)
  bool Converged = true;
};

/// Premultiplied RGBA of a surface crossing; @p user is passed through.
using SurfaceShadeFunction = RGBA (*)(void* user, const IsovalueCrossing& crossing);

/**
 * Integral over [0, @p length] of table @p tf along s(t) with the surfaces at
 * @p crossings (sorted by t, inside [0, length], e.g. from SurfaceCrossings)
 * composited in order; @p shade gives each surface's premultiplied RGBA.
 */
HOV_EXPORT IsosurfaceSegmentResult IntegrateWithSurfaces(const TransferFunction& tf,
  const Polynomial& s, double length, const IsovalueCrossing* crossings, int crossingCount,
  SurfaceShadeFunction shade, void* user, const PolynomialSegmentSettings& settings);

/**
 * Three fields (HIAC 5): the surfaces at @p crossings (of a third field s3,
 * from SurfaceCrossings(s3, ...)) embedded in the volume whose extinction
 * comes from @p extinction at s1 and colour from @p color at s2
 * (IntegrateTwoFields between the crossings).
 */
HOV_EXPORT IsosurfaceSegmentResult IntegrateWithSurfaces(const TransferFunction& extinction,
  const Polynomial& s1, const TransferFunction& color, const Polynomial& s2, double length,
  const IsovalueCrossing* crossings, int crossingCount, SurfaceShadeFunction shade, void* user,
  const PolynomialSegmentSettings& settings);

/// IntegrateWithSurfaces for any callable RGBA(const IsovalueCrossing&).
template <class F>
IsosurfaceSegmentResult IntegrateWithSurfaces(const TransferFunction& tf, const Polynomial& s,
  double length, const IsovalueCrossing* crossings, int crossingCount, F&& shade,
  const PolynomialSegmentSettings& settings)
{
  using Fn = std::remove_reference_t<F>;
  return IntegrateWithSurfaces(
    tf, s, length, crossings, crossingCount,
    [](void* user, const IsovalueCrossing& c) { return (*static_cast<Fn*>(user))(c); },
    const_cast<void*>(static_cast<const void*>(&shade)), settings);
}
}

#endif
