/**
 * @file hovCurvedSegment.h
 * @brief ElVis's ray-segment categorization (E / PS / S, ElVis section 5)
 * on a rigorous range enclosure, breakpoint location on the field restricted
 * to the ray, and the volume-rendering integral of one ray segment inside a
 * (curved) Lagrange cell with the exact polynomial-segment machinery.
 *
 * Categorization (CategorizeSegment), for the field range [lo, hi] of the
 * segment (an enclosure: hovEnclosure.h) and the table of
 * hovTransferFunction.h (colour and extinction piecewise linear in s):
 *  - Empty (E): extinction 0 on [lo, hi] (and, Wilhelms-Van Gelder, emission
 *    0 too): the segment contributes nothing (empty-space skipping, 5.2.1);
 *  - PiecewiseSmooth (PS): a table node (breakpoint b_k) lies in [lo, hi];
 *  - Smooth (S): otherwise (one linear piece of the table on the range).
 * OcclusionOnly (5.2.2): the colour (Williams-Max chromaticity, or WVG
 * emission) is 0 on the range but the extinction is not. Since the
 * enclosure is rigorous, E and S are never wrong (a PS verdict may be
 * conservative: a node in the enclosure but not in the true range).
 * IntegrateCurvedSegment first encloses with a coarse remainder tolerance
 * (1e-3 of the field scale, ~30x fewer Taylor-model pieces on curved
 * segments) and refines to Enclosure.RemainderTolerance only when a PS
 * verdict could change what is done: the table is zero somewhere on the
 * range (may become E), or the ElVis rule is selected (may become S).
 * Its first Taylor model doubles as RepresentFieldOnSegment's affine test.
 *
 * Integration (IntegrateCurvedSegment), the improvement on ElVis's
 * "trapezoid on PS": the field g(t) on [t0, t1] is represented by pieces
 * G_i (Bernstein form, any degree <= 30) with an error bound e_i:
 *  - affine geometry (the enclosure's single Taylor model has a remainder
 *    <= FieldTolerance x field scale): G = the exact polynomial f(pc(t))
 *    (hovLagrangeRestriction.h), e = its rounding bound (rigorous);
 *  - curved geometry: g sampled at the 17 Chebyshev points of each piece
 *    (Newton inversion, warm-started), interpolated (degree 16), e =
 *    2 (|c_15| + |c_16|) + 64 eps sum |c_k| + 1e-13 x scale (an ESTIMATE,
 *    reliable for the geometric coefficient decay of these analytic g; the
 *    same rule as hovCellRestriction's non-affine path); pieces bisected
 *    until e <= FieldTolerance x scale (at most MaxPieces).
 * Breakpoints (PS only): for every table node b_k in a piece's hull,
 * BernsteinRoots(G_i = b_k) (Descartes-rule isolation, hovBernstein.h)
 * gives every crossing; on curved pieces each root is then polished by
 * safeguarded Newton on the exact g (g' = grad f . J^-1 d). The piece is
 * cut there, so every sub-piece is smooth for the table; each sub-piece is
 * approximated by a polynomial of degree <= 8 with a rigorous bound
 * (ApproximateBernstein; bisected while that bound exceeds the field
 * tolerance) and integrated exactly in depth with Gauss-Kronrod colour by
 * IntegratePolynomialScalar (hovPolynomialSegment.h), front to back.
 * ErrorEstimate = sum of the quadrature estimates + L (S_c tau_max + c_max
 * S_tau) e_max, S the table's largest slopes d/ds over the range (a field
 * error e moves colour and extinction by at most S e; table jumps excluded).
 *
 * Measured (TestCurvedSegment, GCC 12 Release), against the independent
 * reference of hovPolynomialTestSupport.h (long double, breakpoints by
 * bisection, adaptive Gauss-Kronrod) with a 4-breakpoint table: ElVis's
 * field x^2 + y^2 + z^2 on an axis-aligned hexahedron of order 2 and 3
 * (affine path), 50 segments, 84 breakpoints located: max RGBA error
 * 4.0e-14; a curved cubic hexahedron (x = r + 0.35 s^2; curved path on
 * every segment), 30 segments: 6.1e-16.
 *
 * Quadrature options (CurvedQuadrature), measured by TestCurvedConvergence
 * (ElVis's f = x^2 + y^2 + z^2 on a cubic hexahedron, 16x16 rays, reference
 * with analytic breakpoints and Boost gauss_kronrod in long double): ElVis
 * trapezoid on PS segments order 2.09, Riemann order 1.00 (PS and S),
 * ElVis Kronrod outer + trapezoid depth on S segments order 2.00; ours with
 * fixed Gauss-Legendre nodes: 1.6e-8 at 32 samples per ray, <= 1e-15 from
 * 64 (spectral; ElVis 5e-4 there); ours adaptive: max error 5.6e-12 /
 * 1.0e-12 / 1.7e-14 at tolerance 1e-3 / 1e-5 / 1e-7.
 *
 * Thread safety: re-entrant (the table and cell are read only); allocates
 * small vectors.
 * @sa hovEnclosure.h, hovPolynomialSegment.h, hovCurvedRayCell.h
 */
#ifndef hovCurvedSegment_h
#define hovCurvedSegment_h

#include "hovCompositing.h"
#include "hovConfig.h"
#include "hovEnclosure.h"
#include "hovPolynomialSegment.h"

#include <functional> // CurvedCellInfo's bounds on demand

namespace hov
{
class GradientOpacityFunction;
class TransferFunction;
struct VolumeShadingSettings;

enum class SegmentCategory
{
  Empty = 0,           ///< E: the transfer function is zero on the range
  PiecewiseSmooth = 1, ///< PS: a breakpoint lies in the range
  Smooth = 2           ///< S: no breakpoint in the range
};

struct SegmentClassification
{
  SegmentCategory Category = SegmentCategory::Empty;
  bool OcclusionOnly = false; ///< colour 0, extinction not (ElVis 5.2.2)
  int FirstNode = 0;          ///< table nodes FirstNode..FirstNode+NodeCount-1 lie in the range
  int NodeCount = 0;
};

/// Categorize the field range [@p lo, @p hi] against @p tf (see file doc).
HOV_EXPORT SegmentClassification CategorizeSegment(
  const TransferFunction& tf, double lo, double hi, EmissionModel emission);

/**
 * Quadrature of a non-empty segment (the categorization and empty-space
 * skipping are the same for all):
 *  - LocatedBreakpoints (ours, default): breakpoints located, exact optical
 *    depth per smooth piece, adaptive Gauss-Kronrod colour to
 *    Quadrature.Tolerance; with Samples > 0 instead a fixed Gauss-Legendre
 *    rule of ~Samples nodes per segment (half shared equally among the
 *    smooth pieces, half by length, >= 1 each) on the exact depth (for
 *    convergence studies);
 *  - ElVis (ElVis 5.2.3): Samples equispaced samples, trapezoid rule for
 *    both the inner (depth) and the outer (colour) integral on PS segments;
 *    on S segments composite 7-15 Gauss-Kronrod outer (max(1, Samples/15)
 *    panels) with the trapezoid rule for the depth on the sorted nodes
 *    (plus both ends);
 *  - Riemann: Samples steps of length L/Samples, left end value per step,
 *    alpha = 1 - exp(-tau h) composited (ElVis's public code's fixed step).
 * The sampled methods read the field from RepresentFieldOnSegment's pieces
 * (exact on the affine path, within FieldTolerance on curved pieces).
 * Implemented in hovCurvedSampling.cxx.
 */
enum class CurvedQuadrature
{
  LocatedBreakpoints = 0,
  ElVis = 1,
  Riemann = 2
};

/// Samples used by ElVis / Riemann when CurvedSegmentSettings::Samples is 0.
constexpr int DefaultSegmentSamples = 64;

struct CurvedSegmentSettings
{
  PolynomialSegmentSettings Quadrature;
  EnclosureSettings Enclosure;
  /// Target of the field representation error, relative to the field scale
  /// (the floor: the budget below may loosen it).
  double FieldTolerance = 1e-10;
  /// Share of Quadrature.Tolerance the field representation may use: the
  /// field target of a segment is loosened to what keeps its field-error
  /// term below this share of the tolerance, spread over FieldBudgetLength
  /// (hovCurvedSegmentDetail.h, FieldTarget); 0 keeps FieldTolerance.
  double FieldErrorShare = 0.25;
  /// World length over which that share is spread (CurvedRayCaster: the
  /// length of all segments of the ray); 0: the segment's own length.
  double FieldBudgetLength = 0.0;
  /// Field pieces allowed per segment (curved geometry).
  int MaxPieces = 64;
  /// Quadrature method (see CurvedQuadrature).
  CurvedQuadrature Method = CurvedQuadrature::LocatedBreakpoints;
  /// Samples per segment of the fixed-sample rules (0: adaptive for
  /// LocatedBreakpoints, DefaultSegmentSamples for ElVis / Riemann).
  int Samples = 0;
  /// A ray stops once its transmittance is at most this (CurvedRayCaster:
  /// no segment is integrated once the opacity is >= 1 - this).
  double TerminationTransmittance = 1e-12;
  /// The volume's own shading and gradient opacity (either non-null: the
  /// segment goes to IntegrateCurvedShadedSegment, hovCurvedShadedSegment.h).
  const VolumeShadingSettings* Shading = nullptr;
  const GradientOpacityFunction* GradientOpacity = nullptr;
};

struct CurvedSegmentResult
{
  RGBA Color;                  ///< premultiplied, front to back
  double ErrorEstimate = 0.0;  ///< quadrature + field-error contribution (max channel)
  /// The field-error part of ErrorEstimate (a tighter quadrature does not reduce it).
  double FieldErrorEstimate = 0.0;
  SegmentClassification Class; ///< from the enclosure
  double Lo = 0.0, Hi = 0.0;   ///< the enclosure
  double FieldError = 0.0;     ///< largest e_i of the field pieces
  int FieldPieces = 0;
  int Breakpoints = 0;         ///< located breakpoint crossings
  int Pieces = 0;              ///< polynomial pieces integrated
  bool ExactField = false;     ///< affine path (rigorous field bound)
  bool Converged = true;
  int Samples = 0;             ///< field samples of the fixed-sample rules (0: adaptive)
};

/**
 * The volume-rendering integral over the ray segment o + t d, t in
 * [@p t0, @p t1] (inside @p cell; t0 at the eye side), with @p pcGuess the
 * parametric coordinates at t0 (may be null); see file doc.
 */
HOV_EXPORT CurvedSegmentResult IntegrateCurvedSegment(const LagrangeCellView& cell,
  const CellDerivativeBounds& bounds, const TransferFunction& tf, const double origin[3],
  const double direction[3], double t0, double t1, const double* pcGuess,
  const CurvedSegmentSettings& settings = CurvedSegmentSettings());

/**
 * What IntegrateCurvedSegment may know about a cell beyond its nodes
 * (CurvedRayCaster keeps it per cell): a rigorous hull of the field over the
 * cell (hovLagrangeHull.h, or CellDerivativeBounds' looser FieldMin/FieldMax),
 * the field scale, the affine map of straight-sided cells, and the
 * second-derivative bounds on demand (costly, ~1 ms for an order-4
 * tetrahedron: asked for only when a segment needs a rigorous enclosure).
 */
struct CurvedCellInfo
{
  double FieldLo = 0.0, FieldHi = 0.0; ///< the field lies in [FieldLo, FieldHi] on the cell
  double FieldScale = 1.0;            ///< as CellDerivativeBounds::FieldScale
  bool Affine = false;                ///< x = X0 + J pc on the whole cell
  double X0[3] = { 0.0, 0.0, 0.0 };
  double InverseJ[9] = {};            ///< J^-1, row-major
  std::function<const CellDerivativeBounds&()> Bounds;
};

/**
 * IntegrateCurvedSegment with a CurvedCellInfo: the cell's hull categorizes
 * first (E: exactly zero); where the hull holds no zero of the table and the
 * method is LocatedBreakpoints, no Taylor-model enclosure is made (the
 * breakpoints are located on the representation, whose own range selects
 * the table nodes): affine cells take the exact field on their parametric
 * line, curved ones the Chebyshev pieces; otherwise the call above with
 * info.Bounds(). The same colour to the field target, the same error terms.
 * @p pcEndGuess: the parametric coordinates at t1 if known (the far end's
 * face crossing), a warm start for the samples.
 */
HOV_EXPORT CurvedSegmentResult IntegrateCurvedSegment(const LagrangeCellView& cell,
  const CurvedCellInfo& info, const TransferFunction& tf, const double origin[3],
  const double direction[3], double t0, double t1, const double* pcGuess,
  const CurvedSegmentSettings& settings = CurvedSegmentSettings(),
  const double* pcEndGuess = nullptr);

/// One piece of the field along the ray: g(t) ~ G((t - T0)/(T1 - T0)), |error| <= Error.
struct FieldPiece
{
  double T0 = 0.0, T1 = 0.0;
  BernsteinPolynomial G;
  double Error = 0.0;
  bool Exact = false; ///< G is the exact polynomial (affine geometry)
  /// Parametric coordinates at T0 and T1 (sampled pieces): warm starts.
  bool HasPC = false;
  double PC0[3] = { 0.0, 0.0, 0.0 }, PC1[3] = { 0.0, 0.0, 0.0 };
  /// Sampled pieces: the parametric coordinates of the ray's points at the
  /// Chebyshev points of the interpolant, T0 + (1 + cos(pi j / n)) / 2 (T1 - T0),
  /// j = 0..n, n = SampleDegree (0: none); PieceCoordinates interpolates them.
  int SampleDegree = 0;
  double SamplePC[17][3] = {};
};

/**
 * The parametric coordinates of the ray point at @p t in a sampled piece
 * (SampleDegree > 0): the barycentric Chebyshev interpolant of SamplePC (a
 * warm start for Newton, as accurate as the field's interpolant is). False if
 * the piece holds no samples.
 */
HOV_EXPORT bool PieceCoordinates(const FieldPiece& piece, double t, double pc[3]);

/**
 * The field representation of IntegrateCurvedSegment (see file doc) into
 * @p out (cleared first). Returns false if an inversion failed.
 */
HOV_EXPORT bool RepresentFieldOnSegment(const LagrangeCellView& cell,
  const CellDerivativeBounds& bounds, const double origin[3], const double direction[3],
  double t0, double t1, const double* pcGuess, const CurvedSegmentSettings& settings,
  std::vector<FieldPiece>& out);

/**
 * Every t in the piece where the field equals @p level (BernsteinRoots on G,
 * polished on the exact field for non-exact pieces), ascending, appended to
 * @p roots. Returns the number appended.
 */
HOV_EXPORT int LocateBreakpoints(const LagrangeCellView& cell, const double origin[3],
  const double direction[3], const FieldPiece& piece, double level, std::vector<double>& roots);
}

#endif
