// Fixed-sample quadratures of a curved ray segment (ElVis, Riemann, fixed
// Gauss-Legendre on located breakpoints): see hovCurvedSampling.h.
#include "hovCurvedSampling.h"

#include "hovGaussKronrod15.h" // XGK, WGK, WG

#include "hovTransferFunction.h" // table values

#include <algorithm> // std::min, std::max
#include <cmath>     // std::exp, std::expm1, std::cos

namespace hov
{
namespace detail
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

/// Table values at one sample: extinction and colour (chromaticity or emission).
struct Sample
{
  double Tau = 0.0;
  double Color[3] = { 0.0, 0.0, 0.0 };
};

/// The field at @p t on the ascending pieces (@p hint walks forward with t).
double FieldAtT(const std::vector<FieldPiece>& pieces, double t, size_t& hint)
{
  while (hint + 1 < pieces.size() && t > pieces[hint].T1)
  {
    ++hint;
  }
  const FieldPiece& p = pieces[hint];
  const double h = p.T1 - p.T0;
  const double y = h > 0.0 ? std::min(std::max((t - p.T0) / h, 0.0), 1.0) : 0.0;
  return EvaluateBernstein(p.G, y);
}

Sample TableAt(const TransferFunction& tf, double s, bool emission)
{
  SegmentEnd v;
  tf.Evaluate(tf.FindIntervalUpward(s), s, emission, v);
  Sample out;
  out.Tau = v.Tau;
  std::copy(v.Color, v.Color + 3, out.Color);
  return out;
}

/// Outer integrand weights: WM c tau, WVG g (times e^-D by the caller).
inline double Emitted(const Sample& v, int c, bool emission)
{
  return emission ? v.Color[c] : v.Color[c] * v.Tau;
}

double MaxDiff(const RGBA& a, const RGBA& b)
{
  return std::max(std::max(std::abs(a.R - b.R), std::abs(a.G - b.G)),
    std::max(std::abs(a.B - b.B), std::abs(a.A - b.A)));
}

/// Trapezoid rule (inner and outer) on samples 0, stride, ..., n-1 of spacing @p h (length).
RGBA Trapezoid(const std::vector<Sample>& v, double h, int stride, bool emission)
{
  RGBA out;
  double depth = 0.0, prevF[3] = { 0.0, 0.0, 0.0 };
  double* rgb[3] = { &out.R, &out.G, &out.B };
  const int n = static_cast<int>(v.size());
  const double hs = h * stride;
  for (int j = 0; j < n; j += stride)
  {
    if (j > 0)
    {
      depth += 0.5 * hs * (v[j - stride].Tau + v[j].Tau);
    }
    const double e = std::exp(-depth);
    for (int c = 0; c < 3; ++c)
    {
      const double f = Emitted(v[j], c, emission) * e;
      if (j > 0)
      {
        *rgb[c] += 0.5 * hs * (prevF[c] + f);
      }
      prevF[c] = f;
    }
  }
  out.A = -std::expm1(-depth);
  return out;
}

/// Fixed-step Riemann sum with @p steps steps of length @p h (left values, every stride-th).
RGBA Riemann(const std::vector<Sample>& v, double h, int stride, bool emission)
{
  RGBA out;
  double transmit = 1.0;
  const double hs = h * stride;
  double* rgb[3] = { &out.R, &out.G, &out.B };
  for (size_t j = 0; j < v.size(); j += stride)
  {
    const double alpha = -std::expm1(-v[j].Tau * hs);
    for (int c = 0; c < 3; ++c)
    {
      *rgb[c] += transmit * (emission ? v[j].Color[c] * hs : v[j].Color[c] * alpha);
    }
    transmit *= 1.0 - alpha;
  }
  out.A = 1.0 - transmit;
  return out;
}

/// ElVis's S rule: composite G7-K15 outer on @p panels equal panels, trapezoid depth on the chain.
void KronrodTrapezoid(const TransferFunction& tf, const std::vector<FieldPiece>& pieces,
  double t0, double t1, double speed, int panels, bool emission, CurvedSegmentResult& result)
{
  // The chain t0, the 15 nodes of each panel (ascending), t1.
  std::vector<double> ts{ t0 };
  const double width = (t1 - t0) / panels;
  for (int p = 0; p < panels; ++p)
  {
    const double mid = t0 + (p + 0.5) * width, half = 0.5 * width;
    for (int i = 0; i < 8; ++i)
    {
      ts.push_back(mid - half * XGK[i]);
    }
    for (int i = 6; i >= 0; --i)
    {
      ts.push_back(mid + half * XGK[i]);
    }
  }
  ts.push_back(t1);
  std::vector<Sample> v(ts.size());
  std::vector<double> depth(ts.size(), 0.0);
  size_t hint = 0;
  for (size_t j = 0; j < ts.size(); ++j)
  {
    v[j] = TableAt(tf, FieldAtT(pieces, ts[j], hint), emission);
    if (j > 0)
    {
      depth[j] = depth[j - 1] + 0.5 * (ts[j] - ts[j - 1]) * speed * (v[j - 1].Tau + v[j].Tau);
    }
  }
  double k[3] = { 0.0, 0.0, 0.0 }, error = 0.0;
  const double halfLength = 0.5 * width * speed;
  for (int p = 0; p < panels; ++p)
  {
    double kp[3] = { 0.0, 0.0, 0.0 }, gp[3] = { 0.0, 0.0, 0.0 };
    for (int q = 0; q < 15; ++q)
    {
      const size_t j = 1 + 15 * p + q;
      const int i = q < 8 ? q : 14 - q; // XGK index of node q
      const double e = std::exp(-depth[j]);
      for (int c = 0; c < 3; ++c)
      {
        const double f = Emitted(v[j], c, emission) * e;
        kp[c] += WGK[i] * f;
        gp[c] += (i % 2 == 1) ? WG[i / 2] * f : 0.0;
      }
    }
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      k[c] += halfLength * kp[c];
      worst = std::max(worst, halfLength * std::abs(kp[c] - gp[c]));
    }
    error += worst;
  }
  result.Color = RGBA{ k[0], k[1], k[2], -std::expm1(-depth.back()) };
  result.ErrorEstimate += error;
  result.Samples += static_cast<int>(ts.size());
}
}

void GaussLegendreUnit(int n, std::vector<double>& x, std::vector<double>& w)
{
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  for (int i = 0; i < n; ++i)
  {
    double z = std::cos(Pi * (i + 0.75) / (n + 0.5)), slope = 1.0;
    for (int iter = 0; iter < 100; ++iter)
    {
      double p0 = 1.0, p1 = z;
      for (int k = 2; k <= n; ++k)
      {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      slope = n * (z * p1 - p0) / (z * z - 1.0);
      const double dz = p1 / slope;
      z -= dz;
      if (std::abs(dz) < 1e-16)
      {
        break;
      }
    }
    x[i] = 0.5 * (1.0 - z); // ascending on [0, 1]
    w[i] = 1.0 / ((1.0 - z * z) * slope * slope);
  }
}

void IntegrateSampledSegment(const TransferFunction& tf, const std::vector<FieldPiece>& pieces,
  bool smooth, double t0, double t1, double speed, const CurvedSegmentSettings& settings,
  CurvedSegmentResult& result)
{
  const bool emission = settings.Quadrature.Emission == EmissionModel::WilhelmsVanGelder;
  const int n = std::max(settings.Samples > 0 ? settings.Samples : DefaultSegmentSamples, 2);
  if (pieces.empty() || !(t1 > t0))
  {
    return;
  }
  if (settings.Method == CurvedQuadrature::ElVis && smooth)
  {
    KronrodTrapezoid(tf, pieces, t0, t1, speed, std::max(1, n / 15), emission, result);
    return;
  }
  const bool riemann = settings.Method == CurvedQuadrature::Riemann;
  // Trapezoid: n samples on [t0, t1] (both ends); Riemann: n left ends of n steps.
  const int intervals = riemann ? n : n - 1;
  const double step = (t1 - t0) / intervals;
  std::vector<Sample> v(n);
  size_t hint = 0;
  for (int j = 0; j < n; ++j)
  {
    const double t = j == n - 1 && !riemann ? t1 : t0 + j * step;
    v[j] = TableAt(tf, FieldAtT(pieces, t, hint), emission);
  }
  const double h = step * speed;
  if (riemann)
  {
    result.Color = Riemann(v, h, 1, emission);
    // First order: Q(h) - Q(2h) estimates the error of Q(h).
    result.ErrorEstimate += n % 2 == 0 ? MaxDiff(result.Color, Riemann(v, h, 2, emission)) : 0.0;
  }
  else
  {
    result.Color = Trapezoid(v, h, 1, emission);
    // Second order: (Q(h) - Q(2h)) / 3.
    result.ErrorEstimate +=
      (n - 1) % 2 == 0 ? MaxDiff(result.Color, Trapezoid(v, h, 2, emission)) / 3.0 : 0.0;
  }
  result.Samples += n;
}

void IntegrateSubPieceFixed(const TransferFunction& tf, const BernsteinPolynomial& g, double a,
  double b, double speed, int nodes, bool emission, CurvedSegmentResult& result)
{
  if (nodes < 1 || !(b > a))
  {
    return;
  }
  if (g.Degree + 1 > MaxBernsteinDegree)
  {
    result.Converged = false; // the depth's antiderivative would not fit
    return;
  }
  // The table interval of the piece, read as exact linear functions of s (unclamped:
  // the Bernstein coefficients may leave the interval).
  const int k = tf.FindIntervalUpward(EvaluateBernstein(g, 0.5));
  const std::vector<double>& xs = tf.GetNodes();
  const int nx = static_cast<int>(xs.size());
  const double scale = emission ? tf.GetEmissionFactor() : 1.0;
  auto linear = [&](double s) {
    Sample out;
    const bool inside = k >= 0 && k < nx - 1;
    const TransferFunction::Node& node = tf.GetNode(k < 0 ? 0 : (inside ? k : nx - 1));
    const double ds = inside ? s - xs[k] : 0.0;
    out.Tau = node.Tau + (inside ? node.DTau : 0.0) * ds;
    out.Color[0] = scale * (node.R + (inside ? node.DR : 0.0) * ds);
    out.Color[1] = scale * (node.G + (inside ? node.DG : 0.0) * ds);
    out.Color[2] = scale * (node.B + (inside ? node.DB : 0.0) * ds);
    return out;
  };
  // Exact depth: tau(s(y)) has Bernstein coefficients tau(B_j); its antiderivative's are
  // the running sums / (n + 1).
  const int n = g.Degree;
  const double length = (b - a) * speed;
  BernsteinPolynomial depth;
  depth.Degree = n + 1;
  for (int j = 0; j <= n; ++j)
  {
    depth.B[j + 1] = depth.B[j] + length * linear(g.B[j]).Tau / (n + 1);
  }
  thread_local std::vector<double> x, w;
  thread_local int cached = 0;
  if (cached != nodes)
  {
    GaussLegendreUnit(nodes, x, w);
    cached = nodes;
  }
  RGBA piece;
  double* rgb[3] = { &piece.R, &piece.G, &piece.B };
  for (int i = 0; i < nodes; ++i)
  {
    const Sample v = linear(EvaluateBernstein(g, x[i]));
    const double e = length * w[i] * std::exp(-EvaluateBernstein(depth, x[i]));
    for (int c = 0; c < 3; ++c)
    {
      *rgb[c] += Emitted(v, c, emission) * e;
    }
  }
  piece.A = -std::expm1(-depth.B[n + 1]);
  CompositeBehind(result.Color, piece);
  result.Samples += nodes;
  ++result.Pieces;
}
}
}
