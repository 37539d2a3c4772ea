/**
 * @file hovRayIntegrator.h
 * @brief Integral over one ray segment on which the scalar varies linearly:
 * split at every transfer-function breakpoint, exact integral per piece,
 * pieces composited front to back.
 *
 * This is the restriction of a linear cell's field to a ray (HIAC section
 * 5.1: slabs between breakpoint contour planes) reduced to one dimension: the
 * scalar goes linearly from sFront at the segment's front (eye side) to sBack
 * at its back, so every node of the table falls at a known fraction of the
 * segment, and between nodes both tau and colour are linear in the ray
 * parameter: exactly the hypothesis of hovSegmentIntegral.
 *
 * Thread safety: re-entrant (the table is read only).
 * @sa hovSegmentIntegral.h, hovTransferFunction.h, hovCompositing.h
 */
#ifndef hovRayIntegrator_h
#define hovRayIntegrator_h

#include "hovCompositing.h"
#include "hovConfig.h"
#include "hovSegmentIntegral.h"

namespace hov
{
class TransferFunction;

struct IntegrationSettings
{
  EmissionModel Emission = EmissionModel::WilliamsMax;
  SegmentMethod Method = SegmentMethod::Exact;
};

/**
 * Premultiplied RGBA of a segment of length @p length (world units) on which
 * the scalar goes linearly from @p sFront to @p sBack. @p pieces, if given,
 * receives the number of linear pieces integrated.
 */
HOV_EXPORT RGBA IntegrateLinearScalar(const TransferFunction& tf, double sFront, double sBack,
  double length, const IntegrationSettings& settings, int* pieces = nullptr);

/**
 * The interval of @p tf that holds the whole scalar range [sMin, sMax] in its
 * interior (so that colour and extinction are linear over it), or -2 if the
 * range meets a node. Cells whose range fits one interval can integrate every
 * segment with IntegrateLinearScalarInInterval(), skipping the search.
 */
HOV_EXPORT int IntervalOfRange(const TransferFunction& tf, double sMin, double sMax);

/**
 * The interval of @p tf in which a segment from @p sFront to @p sBack lies
 * entirely (both finite): the one IntegrateLinearScalar() integrates it in as a
 * single piece; -2 if the segment crosses a node (several pieces).
 */
HOV_EXPORT int OnePieceInterval(const TransferFunction& tf, double sFront, double sBack);

/// IntegrateLinearScalar() for a segment known to lie in interval @p interval
/// (from IntervalOfRange()): one piece, no search.
HOV_EXPORT RGBA IntegrateLinearScalarInInterval(const TransferFunction& tf, int interval,
  double sFront, double sBack, double length, const IntegrationSettings& settings);
}

#endif
