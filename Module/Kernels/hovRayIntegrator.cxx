#include "hovRayIntegrator.h"

#include "hovTransferFunction.h" // the table walked here

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
  const bool emission = settings.Emission == EmissionModel::WilhelmsVanGelder;
  const std::vector<double>& nodes = tf.GetNodes();
  const int n = static_cast<int>(nodes.size());
  const double ds = sBack - sFront;
  SegmentEnd front, back;
  {
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
  }
  {
    // Walk the intervals from the front value toward the back value. Interval k
    // spans [nodes[k], nodes[k+1]]; -1 and n-1 are the clamped outer regions.
    const bool up = ds > 0.0;
    int k = up ? tf.FindIntervalUpward(sFront) : tf.FindIntervalDownward(sFront);
    // Fractions along the segment are (s - sFront)/ds; if ds overflows (s
    // spanning more than the double range) they are taken on halved values.
    const double scale = std::isfinite(ds) ? 1.0 : 0.5;
    const double invDs = 1.0 / (scale * sBack - scale * sFront);
    double xPrev = 0.0; // fraction of the segment already integrated
    double sPrev = sFront;
    while (true)
    {
      // Where this interval ends along the ray (the next node in walking direction).
      double sNext = sBack, xNext = 1.0;
      bool last = true;
      if (up && k + 1 < n && nodes[k + 1] < sBack)
      {
        sNext = nodes[k + 1];
        last = false;
      }
      else if (!up && k >= 0 && nodes[k] > sBack)
      {
        sNext = nodes[k];
        last = false;
      }
      if (!last)
      {
        xNext = (scale * sNext - scale * sFront) * invDs;
      }
      const double pieceLength = length * (xNext - xPrev);
      if (pieceLength > 0.0)
      {
        tf.Evaluate(k, sPrev, emission, front);
        tf.Evaluate(k, sNext, emission, back);
        CompositeBehind(accum, IntegrateSegment(pieceLength, front, back, settings.Emission, settings.Method));
        ++count;
        if (accum.A >= 1.0)
        {
          break; // opaque: nothing behind is visible
        }
      }
      if (last)
      {
        break;
      }
      xPrev = xNext;
      sPrev = sNext;
      k += up ? 1 : -1;
    }
  }
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
