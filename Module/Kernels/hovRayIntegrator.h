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
}

#endif
