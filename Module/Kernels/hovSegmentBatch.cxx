#include "hovSegmentBatch.h"

#include "hovThinSeries.h"       // the scalar kernel's series and term counts
#include "hovTransferFunction.h" // Evaluate, interval search

#include <algorithm> // std::max, std::min
#include <cmath>     // std::isfinite

namespace hov
{
namespace
{
using detail::Thin;

/// Segments evaluated side by side (a multiple of the SIMD width the
/// compiler vectorises the lane loops to: 2 for SSE2, 4 for AVX).
constexpr int Lanes = 4;

/**
 * The thin Williams-Max series of hovSegmentIntegral.cxx (ThinWilliamsMax)
 * for Lanes segments with the same number of terms: the same operations in
 * the same order per lane, so each lane's w = WFront (before clamping) and
 * alpha equal the scalar kernel's bit for bit.
 */
void ThinWilliamsMaxLanes(int terms, const double* a, const double* d1, double* w, double* alpha)
{
  double r[Lanes], d2[Lanes];
  double wOdd[Lanes] = {}, wEven[Lanes] = {}, aOdd[Lanes] = {}, aEven[Lanes] = {};
  for (int l = 0; l < Lanes; ++l)
  {
    r[l] = a[l] / d1[l];
    d2[l] = d1[l] * d1[l];
  }
  for (int n = terms; n >= 1; --n)
  {
    // q_n(r) = sum_j P0[n][n-j] r^j by Horner's rule (the scalar kernel's q[n]).
    const double* p = Thin.P0[n];
    double h[Lanes];
    for (int l = 0; l < Lanes; ++l)
    {
      h[l] = p[0];
    }
    for (int j = 1; j <= n; ++j)
    {
      for (int l = 0; l < Lanes; ++l)
      {
        h[l] = h[l] * r[l] + p[j];
      }
    }
    // Outer Horner chains in d1^2 on odd and even terms.
    const double f = Thin.InvFactorial[n];
    if (n % 2)
    {
      for (int l = 0; l < Lanes; ++l)
      {
        wOdd[l] = wOdd[l] * d2[l] + h[l];
        aOdd[l] = aOdd[l] * d2[l] + f;
      }
    }
    else
    {
      for (int l = 0; l < Lanes; ++l)
      {
        wEven[l] = wEven[l] * d2[l] + h[l];
        aEven[l] = aEven[l] * d2[l] + f;
      }
    }
  }
  for (int l = 0; l < Lanes; ++l)
  {
    w[l] = d1[l] * wOdd[l] - d2[l] * wEven[l];
    alpha[l] = d1[l] * aOdd[l] - d2[l] * aEven[l];
  }
}
}

long long SegmentBatch::Integrate(const TransferFunction& tf, const IntegrationSettings& settings,
  const SegmentJob* jobs, int count, RGBA* out)
{
  const bool batched =
    settings.Emission == EmissionModel::WilliamsMax && settings.Method == SegmentMethod::Exact;
  long long pieces = 0;
  this->Items.clear();
  int perTerms[detail::MaxThinOrder + 2] = {};
  for (int i = 0; i < count; ++i)
  {
    const SegmentJob& job = jobs[i];
    int k = job.Interval;
    if (k < -1)
    {
      // IntegrateLinearScalar(): nothing for invalid input, a walk over the
      // intervals if the segment crosses a node, else one piece in k.
      if (!(job.Length > 0.0) || !std::isfinite(job.SFront) || !std::isfinite(job.SBack) ||
        tf.GetNumberOfNodes() == 0)
      {
        out[i] = RGBA();
        continue;
      }
      k = OnePieceInterval(tf, job.SFront, job.SBack);
      if (k < -1)
      {
        int p = 0;
        out[i] = IntegrateLinearScalar(tf, job.SFront, job.SBack, job.Length, settings, &p);
        pieces += p;
        continue;
      }
    }
    ++pieces;
    if (!batched || !(job.Length > 0.0) || !std::isfinite(job.SFront) || !std::isfinite(job.SBack))
    {
      out[i] = IntegrateLinearScalarInInterval(tf, k, job.SFront, job.SBack, job.Length, settings);
      continue;
    }
    // IntegrateLinearScalarInInterval() -> IntegrateSegment() -> ExactSegmentWeights(),
    // taking the thin branch aside for the lanes.
    SegmentEnd front, back;
    tf.Evaluate(k, job.SFront, false, front);
    tf.Evaluate(k, job.SBack, false, back);
    const double depthFront = std::max(front.Tau, 0.0) * job.Length;
    const double depthBack = std::max(back.Tau, 0.0) * job.Length;
    const double a = std::min(depthFront, detail::DepthCap);
    const double c = std::min(depthBack, detail::DepthCap);
    const double d1 = 0.5 * (a + c);
    if (!std::isfinite(depthFront) || !std::isfinite(depthBack) || !(d1 > 0.0) ||
      d1 > detail::ThinDepth)
    {
      out[i] = IntegrateSegment(job.Length, front, back, settings.Emission, settings.Method);
      continue;
    }
    ThinItem item;
    item.A = a;
    item.D1 = d1;
    for (int ch = 0; ch < 3; ++ch)
    {
      item.Front[ch] = front.Color[ch];
      item.Back[ch] = back.Color[ch];
    }
    item.Index = i;
    item.Terms = detail::ThinTerms()(d1);
    ++perTerms[item.Terms + 1];
    this->Items.push_back(item);
  }

  // Group the thin segments by number of terms (counting sort), Lanes at a time.
  const int numItems = static_cast<int>(this->Items.size());
  for (int t = 0; t <= detail::MaxThinOrder; ++t)
  {
    perTerms[t + 1] += perTerms[t];
  }
  this->Order.resize(numItems);
  for (int n = 0; n < numItems; ++n)
  {
    this->Order[perTerms[this->Items[n].Terms]++] = n;
  }
  for (int first = 0; first < numItems; first += Lanes)
  {
    // A block may mix two term counts at a bucket boundary: it then runs with
    // the larger count for the lanes that have it and again for the others.
    const int last = std::min(first + Lanes, numItems);
    int done = first;
    while (done < last)
    {
      const int terms = this->Items[this->Order[done]].Terms;
      double a[Lanes], d1[Lanes], w[Lanes], alpha[Lanes];
      int lanes = 0;
      for (int m = done; m < last && this->Items[this->Order[m]].Terms == terms; ++m, ++lanes)
      {
        a[lanes] = this->Items[this->Order[m]].A;
        d1[lanes] = this->Items[this->Order[m]].D1;
      }
      for (int l = lanes; l < Lanes; ++l)
      {
        a[l] = 0.0; // padding: any valid thin segment
        d1[l] = 1.0 / 8.0;
      }
      ThinWilliamsMaxLanes(terms, a, d1, w, alpha);
      for (int l = 0; l < lanes; ++l)
      {
        const ThinItem& item = this->Items[this->Order[done + l]];
        // As ThinWeights() and IntegrateSegment().
        const double wf = std::max(0.0, w[l]);
        const double wb = std::max(0.0, alpha[l] - w[l]);
        RGBA& o = out[item.Index];
        o.A = alpha[l];
        o.R = wf * item.Front[0] + wb * item.Back[0];
        o.G = wf * item.Front[1] + wb * item.Back[1];
        o.B = wf * item.Front[2] + wb * item.Back[2];
      }
      done += lanes;
    }
  }
  return pieces;
}
}
