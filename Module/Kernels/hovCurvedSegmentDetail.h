/**
 * @file hovCurvedSegmentDetail.h
 * @brief The parts IntegrateCurvedSegment (hovCurvedSegment.h) is made of,
 * shared by its two entry points (with precomputed derivative bounds, and
 * with the per-cell CurvedCellInfo of the ray caster). Internal (namespace
 * hov::detail).
 *
 * The field error budget (FieldTarget): a field representation error e on a
 * segment of length L moves its colour by at most
 *   L (S_c tau_max + c_max S_tau) e + [opaque] S_c e
 * (S the table's largest slopes d/ds, tau_max and c_max its largest values
 * over the range; the second term where the medium is opaque). The target
 * e_seg = share x Tolerance / (sens x Lbudget + [opaque] S_c), with sens
 * evaluated over a range containing the segment's, keeps that contribution
 * below share x Tolerance x L / Lbudget: summed over the segments of a ray
 * whose lengths add up to Lbudget, below share x Tolerance per pixel. It is
 * never below FieldTolerance x scale (the previous, fixed target) and never
 * above share x Tolerance x scale (a table jump located off by e / |g'|
 * changes a pixel by about jump x e / scale; the sensitivity skips jumps).
 *
 * Thread safety: re-entrant; small heap vectors.
 * @sa hovCurvedSegment.h, hovCurvedSampling.h
 */
#ifndef hovCurvedSegmentDetail_h
#define hovCurvedSegmentDetail_h

#include "hovCurvedSegment.h"

#include <vector> // pieces

namespace hov
{
class TransferFunction;
namespace detail
{
/// Table values at s (Find + Evaluate).
SegmentEnd ValueAt(const TransferFunction& tf, double s, bool emission);

/// True if the table's extinction (and, WVG, emission) is 0 somewhere on [lo, hi].
bool MayBeEmpty(const TransferFunction& tf, double lo, double hi, EmissionModel emission);

/// Largest |value|s and slopes d/ds of the table on [lo, hi] (jumps skipped).
struct TableSensitivity
{
  double TauMax = 0.0, ColorMax = 0.0, TauSlope = 0.0, ColorSlope = 0.0;
  /// Infinite extinction somewhere (an opaque medium: opacity 1 in
  /// GPU-compatible semantics); TauMax and TauSlope cover the finite values.
  bool Opaque = false;
};
TableSensitivity Sensitivity(const TransferFunction& tf, double lo, double hi, bool emission);

/**
 * The absolute field tolerance of a segment of length @p length (world) whose
 * field lies in [@p lo, @p hi] (see the file doc): max(FieldTolerance x
 * @p scale, the budget), the budget spread over settings.FieldBudgetLength
 * (the segment's own length if that is 0).
 */
double FieldTarget(const TransferFunction& tf, double lo, double hi, double scale, double length,
  const CurvedSegmentSettings& settings);

/// A segment through a cell whose node scalars are all equal: one exact table
/// value (see hovCurvedSegment.cxx). True if the cell is such a cell.
bool IntegrateConstantCell(const LagrangeCellView& cell, const TransferFunction& tf,
  const double direction[3], double t0, double t1, const CurvedSegmentSettings& settings,
  CurvedSegmentResult& result);

/// Order-1 cells: the pieces' end values clamped to the node range.
void ClampOrderOneEnds(const LagrangeCellView& cell, std::vector<FieldPiece>& pieces);

/**
 * The located-breakpoint integral of the represented field (@p pieces,
 * ascending, covering [t0, t1], inside [@p lo, @p hi]): cut at every crossing
 * of the table nodes of result.Class, each sub-piece approximated to
 * @p fieldTarget and integrated exactly in depth; adds the field-error term
 * to result.ErrorEstimate.
 */
void IntegrateRepresentedField(const LagrangeCellView& cell, const TransferFunction& tf,
  const double origin[3], const double direction[3], double t0, double t1,
  const std::vector<FieldPiece>& pieces, double lo, double hi, double fieldTarget,
  const CurvedSegmentSettings& settings, CurvedSegmentResult& result);
}
}

#endif
