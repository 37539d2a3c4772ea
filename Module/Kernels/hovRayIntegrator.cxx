#include "hovRayIntegrator.h"

#include "hovBreakpointWalk.h"   // ForEachLinearPiece
#include "hovTransferFunction.h" // the table

#include <cmath> // isfinite

namespace hov
{
RGBA IntegrateLinearScalar(const TransferFunction& tf, double sFront, double sBack, double length,
  const IntegrationSettings& settings, int* pieces)
{
  RGBA accum;
  int count = 0;
  if (!(length > 0.0) || !std::isfinite(sFront) || !std::isfinite(sBack) || tf.GetNumberOfNodes() == 0)
  {
    if (pieces)
    {
      *pieces = 0;
    }
    return accum;
  }
  // Fast path (most segments): both ends in one interval, one piece.
  const int k = OnePieceInterval(tf, sFront, sBack);
  if (k >= -1)
  {
    if (pieces)
    {
      *pieces = 1;
    }
    return IntegrateLinearScalarInInterval(tf, k, sFront, sBack, length, settings);
  }
  // Across nodes: the pieces between them, front to back, until opaque.
  const bool emission = settings.Emission == EmissionModel::WilhelmsVanGelder;
  const int start = sBack - sFront > 0.0 ? tf.FindIntervalUpward(sFront) : tf.FindIntervalDownward(sFront);
  ForEachLinearPiece(tf, start, sFront, sBack, length,
    [&](int interval, double s0, double s1, double pieceLength) {
      SegmentEnd front, back;
      tf.Evaluate(interval, s0, emission, front);
      tf.Evaluate(interval, s1, emission, back);
      CompositeBehind(
        accum, IntegrateSegment(pieceLength, front, back, settings.Emission, settings.Method));
      ++count;
      return !(accum.A >= 1.0); // opaque: nothing behind is visible
    });
  if (pieces)
  {
    *pieces = count;
  }
  return accum;
}

int OnePieceInterval(const TransferFunction& tf, double sFront, double sBack)
{
  const std::vector<double>& nodes = tf.GetNodes();
  const int n = static_cast<int>(nodes.size());
  const bool up = sBack - sFront >= 0.0;
  const int k = up ? tf.FindIntervalUpward(sFront) : tf.FindIntervalDownward(sFront);
  return (up ? (k + 1 >= n || nodes[k + 1] >= sBack) : (k < 0 || nodes[k] <= sBack)) ? k : -2;
}

int IntervalOfRange(const TransferFunction& tf, double sMin, double sMax)
{
  const std::vector<double>& nodes = tf.GetNodes();
  const int n = static_cast<int>(nodes.size());
  if (n == 0 || !std::isfinite(sMin) || !std::isfinite(sMax) || sMin > sMax)
  {
    return -2;
  }
  const int k = tf.FindIntervalUpward(sMin);
  const bool lowerOk = k < 0 || nodes[k] < sMin;      // strictly inside: no jump at the end
  const bool upperOk = k + 1 >= n || sMax < nodes[k + 1];
  return lowerOk && upperOk ? k : -2;
}

RGBA IntegrateLinearScalarInInterval(const TransferFunction& tf, int interval, double sFront,
  double sBack, double length, const IntegrationSettings& settings)
{
  if (!(length > 0.0) || !std::isfinite(sFront) || !std::isfinite(sBack))
  {
    return RGBA();
  }
  const bool emission = settings.Emission == EmissionModel::WilhelmsVanGelder;
  SegmentEnd front, back;
  tf.Evaluate(interval, sFront, emission, front);
  tf.Evaluate(interval, sBack, emission, back);
  return IntegrateSegment(length, front, back, settings.Emission, settings.Method);
}
}
