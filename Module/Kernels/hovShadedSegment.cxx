#include "hovShadedSegment.h"

#include "hovChebyshevFit.h" // the cosines and the DCT

#include "hovBreakpointThinning.h" // which mergeable breakpoints are kept
#include "hovGradientOpacity.h"  // gamma(|g|)
#include "hovTransferFunction.h" // extinction and colour at s

#include <algorithm> // sort, unique, min, max
#include <cmath>     // exp, expm1, fabs, isfinite, isinf
#include <limits>    // infinity

namespace hov
{
using detail::Thinning;

namespace
{
// Chebyshev degree per panel: 17 samples. Polynomial integrands of degree
// <= N - 3 have a zero tail (exact); analytic ones converge like rho^-N.
// The cosines and the DCT are the restriction fits' (hovChebyshevFit.h).
constexpr int N = detail::ChebN;
using detail::ChebyshevCosine;
constexpr const double* CosTable = detail::ChebyshevCosines;
// Integration stops once the transmittance is below this times Tolerance / R:
// what lies behind changes the colour by less than 1e-3 of the tolerance.
constexpr double StopFactor = 1e-3;
// Bisection stack size (MaxDepth is clamped below it).
constexpr int StackSize = 64;

/// cos(pi k j / N) for k in [0, N + 1], j in [0, N], looked up once (the
/// depth evaluation of every panel; row k contiguous in j).
struct CosProducts
{
  double V[N + 2][N + 1];
  CosProducts()
  {
    for (int k = 0; k <= N + 1; ++k)
    {
      for (int j = 0; j <= N; ++j)
      {
        this->V[k][j] = ChebyshevCosine(k * j);
      }
    }
  }
};
/// The table, built once (thread-safe initialisation).
const CosProducts& CosKJ()
{
  static const CosProducts table;
  return table;
}

/// DCT-I: coefficients a[0..N] of the interpolant of v at the Lobatto points
/// x_j = cos(pi j/N) (the restriction fits' DCT).
void Chebyshev(const double v[N + 1], double a[N + 1])
{
  detail::ChebyshevCoefficients(v, a);
}

double Tail(const double a[N + 1])
{
  return std::fabs(a[N - 2]) + std::fabs(a[N - 1]) + std::fabs(a[N]);
}

// A tail within this of the sum of its function's |coefficients| is the
// transform's rounding: bisecting cannot make it smaller. A panel whose tails
// are all that small is accepted even if its weighted estimate misses the
// target (colours far beyond [0, 1], e.g. a table colour of 1e300, where the
// panel budget went on rounding noise and the rest of the segment was left
// coarse); Converged still reports the target.
constexpr double RoundingFloor = 16.0 * 2.220446049250313e-16;

/// True if Tail(a) is at the rounding of the coefficients a.
bool TailAtRounding(const double a[N + 1])
{
  double sum = 0.0;
  for (int k = 0; k <= N; ++k)
  {
    sum += std::fabs(a[k]);
  }
  return std::isfinite(sum) && Tail(a) <= RoundingFloor * sum; // an overflowed transform is not
}

struct Context
{
  const TransferFunction* Tf;
  FieldGradientSampler Sampler;
  void* User;
  const VolumeShadingSettings* Shading;
  const GradientOpacityFunction* GO;
  const SegmentRay* Ray;
  /// Directional lights: the lighting's per-ray part, prepared once (else null).
  const DirectionalShading* Directional = nullptr;
  bool Emission = false; // Wilhelms-Van Gelder
  bool StopUnconverged = false;
  int EvaluationsLeft = 0; // panels evaluated, accepted or not (StopUnconverged)
  double EmissionFactor = 1.0;
  double MaxColor = 1.0;
  int Samples = 0;
  bool Bad = false;
};

/// Interval of the table for s: @p hint if s lies in it (a piece's interval), else a search.
int IntervalFor(const TransferFunction& tf, double s, int hint)
{
  const std::vector<double>& x = tf.GetNodes();
  const int n = static_cast<int>(x.size());
  if (hint >= -1 && hint < n && (hint < 0 || x[hint] <= s) && (hint + 1 >= n || s <= x[hint + 1]))
  {
    return hint;
  }
  return tf.FindIntervalUpward(s);
}

/// Extinction, emission and shaded chromaticity at t. Non-finite: transparent.
void Sample(Context& ctx, double t, int hint, double& tau, double e[3], double c[3])
{
  double s = 0.0, g[3] = { 0.0, 0.0, 0.0 };
  ctx.Sampler(ctx.User, t, s, g);
  ++ctx.Samples;
  tau = 0.0;
  e[0] = e[1] = e[2] = c[0] = c[1] = c[2] = 0.0;
  if (!std::isfinite(s))
  {
    ctx.Bad = true;
    return;
  }
  SegmentEnd v;
  ctx.Tf->Evaluate(IntervalFor(*ctx.Tf, s, hint), s, false, v);
  const double gamma = ctx.GO ? ctx.GO->EvaluateGradient(g) : 1.0;
  tau = gamma > 0.0 ? gamma * v.Tau : 0.0;
  c[0] = v.Color[0];
  c[1] = v.Color[1];
  c[2] = v.Color[2];
  if (ctx.Directional)
  {
    ApplyShading(ComputeShadingTransform(*ctx.Directional, g), c);
  }
  else if (ctx.Shading->Shade)
  {
    const SegmentRay& r = *ctx.Ray;
    const double point[3] = { r.Origin[0] + t * r.Direction[0], r.Origin[1] + t * r.Direction[1],
      r.Origin[2] + t * r.Direction[2] };
    const double toViewer[3] = { -r.Direction[0], -r.Direction[1], -r.Direction[2] };
    ApplyShading(ComputeShadingTransform(*ctx.Shading, g, point, toViewer), c);
  }
  for (int i = 0; i < 3; ++i)
  {
    ctx.MaxColor = std::max(ctx.MaxColor, std::fabs(c[i]));
    e[i] = ctx.Emission ? ctx.EmissionFactor * c[i] : c[i] * tau;
  }
  if (!std::isfinite(tau) || !std::isfinite(e[0] + e[1] + e[2]))
  {
    ctx.Bad = true; // infinite extinction inside a finite piece: missing breakpoints
    tau = 0.0;
    e[0] = e[1] = e[2] = 0.0; // c is kept: the opaque piece's front colour
  }
}

struct Panel
{
  double Depth = 0.0;
  double C[3] = { 0.0, 0.0, 0.0 };
  double ErrDepth = 0.0;
  double ErrColor[3] = { 0.0, 0.0, 0.0 };
  bool AtRounding = true; ///< every tail at its coefficients' rounding (TailAtRounding)
};

/// Spectral integration of one panel [a, b] (file doc).
Panel IntegratePanel(Context& ctx, double a, double b, int hint)
{
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  double tau[N + 1], e[3][N + 1], c[3];
  for (int j = 0; j <= N; ++j)
  {
    const double t = j == 0 ? b : (j == N ? a : mid + half * CosTable[j]);
    double ej[3];
    Sample(ctx, t, hint, tau[j], ej, c);
    for (int i = 0; i < 3; ++i)
    {
      e[i][j] = ej[i];
    }
  }
  Panel out;
  double at[N + 1];
  Chebyshev(tau, at);
  // Indefinite integral from x = -1: coefficients bc[0..N+1] of the Chebyshev series.
  double bc[N + 2];
  bc[1] = at[0] - 0.5 * at[2];
  for (int k = 2; k <= N + 1; ++k)
  {
    const double below = at[k - 1];
    const double above = k + 1 <= N ? at[k + 1] : 0.0;
    bc[k] = (below - above) / (2.0 * k);
  }
  bc[0] = 0.0;
  for (int k = 1; k <= N + 1; ++k)
  {
    bc[0] -= (k % 2 ? -1.0 : 1.0) * bc[k];
  }
  // depth_j = half sum_k bc_k cos(pi k j/N), each sum in k order; all j at once.
  double depth[N + 1] = {};
  const CosProducts& cosKJ = CosKJ();
  for (int k = 0; k <= N + 1; ++k)
  {
    const double* row = cosKJ.V[k];
    const double bk = bc[k];
    for (int j = 0; j <= N; ++j)
    {
      depth[j] += bk * row[j];
    }
  }
  for (int j = 0; j <= N; ++j)
  {
    depth[j] *= half;
  }
  out.Depth = std::max(depth[0], 0.0);
  out.ErrDepth = (b - a) * Tail(at);
  out.AtRounding = TailAtRounding(at);
  for (int i = 0; i < 3; ++i)
  {
    double f[N + 1], af[N + 1];
    for (int j = 0; j <= N; ++j)
    {
      f[j] = e[i][j] * std::exp(-depth[j]);
    }
    Chebyshev(f, af);
    double sum = 0.0;
    for (int k = 0; k <= N; k += 2)
    {
      sum += af[k] * 2.0 / (1.0 - static_cast<double>(k) * k);
    }
    out.C[i] = half * sum;
    out.ErrColor[i] = (b - a) * Tail(af);
    out.AtRounding = out.AtRounding && TailAtRounding(af);
  }
  return out;
}

/// Integrates the piece [p0, p1] into @p res; false once nothing behind can show.
bool IntegratePiece(Context& ctx, double p0, double p1, double length, double budgetPerLength,
  int maxDepth, int& panelsLeft, ShadedSegmentResult& res)
{
  // The piece's table interval, and the opaque case, from its midpoint.
  double sMid = 0.0, gMid[3];
  ctx.Sampler(ctx.User, 0.5 * (p0 + p1), sMid, gMid);
  ++ctx.Samples;
  const int hint = std::isfinite(sMid) ? ctx.Tf->FindIntervalUpward(sMid) : -1;
  if (std::isfinite(sMid))
  {
    SegmentEnd v;
    ctx.Tf->Evaluate(hint, sMid, false, v);
    const double gamma = ctx.GO ? ctx.GO->EvaluateGradient(gMid) : 1.0;
    if (std::isinf(v.Tau) && gamma > 0.0)
    {
      double tau, e[3], c[3];
      const bool bad = ctx.Bad;
      Sample(ctx, p0, hint, tau, e, c); // tau = +inf here is expected
      ctx.Bad = bad;
      const double w = ctx.Emission ? 0.0 : 1.0; // Williams-Max: the front colour; WVG: nothing
      CompositeBehind(res.Color, RGBA{ w * c[0], w * c[1], w * c[2], 1.0 });
      return false;
    }
  }
  double ends[StackSize];
  int depths[StackSize];
  int top = 0;
  ends[0] = p1;
  depths[0] = 0;
  double a = p0;
  while (top >= 0)
  {
    const double b = ends[top];
    if (ctx.StopUnconverged && --ctx.EvaluationsLeft < 0)
    {
      res.Converged = false;
      return false; // out of evaluations: the caller has another route
    }
    const Panel panel = IntegratePanel(ctx, a, b, hint);
    const double transmit = 1.0 - res.Color.A;
    const double behind = ctx.Emission
      ? ctx.EmissionFactor * ctx.MaxColor * (length - b) + 1.0
      : ctx.MaxColor;
    double err = 0.0;
    for (int i = 0; i < 3; ++i)
    {
      err = std::max(err, panel.ErrColor[i] + panel.ErrDepth * (std::fabs(panel.C[i]) + behind));
    }
    err = std::max(err, panel.ErrDepth); // the opacity
    const bool ok = transmit * err <= budgetPerLength * (b - a);
    const double mid = 0.5 * (a + b);
    if (!ok && !panel.AtRounding && depths[top] < maxDepth && panelsLeft > 1 && top + 1 < StackSize && mid > a && mid < b)
    {
      ++depths[top];
      ++top;
      ends[top] = mid;
      depths[top] = depths[top - 1];
      continue;
    }
    res.Converged = res.Converged && ok;
    if (!ok && ctx.StopUnconverged)
    {
      return false; // the caller has another route
    }
    --panelsLeft;
    ++res.Panels;
    res.ErrorEstimate += transmit * err;
    CompositeBehind(res.Color, RGBA{ panel.C[0], panel.C[1], panel.C[2], -std::expm1(-panel.Depth) });
    a = b;
    --top;
    const double left = 1.0 - res.Color.A;
    if (left <= StopFactor * budgetPerLength * length / behind)
    {
      res.ErrorEstimate += left * behind;
      return false;
    }
  }
  return true;
}

struct PolynomialField
{
  const Polynomial* S;
  const Polynomial* G;
};

void SamplePolynomial(void* user, double t, double& value, double gradient[3])
{
  const PolynomialField& f = *static_cast<const PolynomialField*>(user);
  value = Evaluate(*f.S, t);
  for (int i = 0; i < 3; ++i)
  {
    gradient[i] = Evaluate(f.G[i], t);
  }
}

/// The pieces left when mergeable breakpoints are stepped over (file doc).
int PiecesAllowed(const ShadedSegmentSettings& settings)
{
  const int half = std::max(std::max(settings.MaxPanels, 1) / 2, 1);
  return settings.MaxPieces > 0 ? std::min(settings.MaxPieces, half) : half;
}

bool Finite(const Polynomial& p)
{
  for (int i = 0; i <= std::min(std::max(p.Degree, 0), Polynomial::MaxDegree); ++i)
  {
    if (!std::isfinite(p.C[i]))
    {
      return false;
    }
  }
  return true;
}
}

ShadedSegmentResult IntegrateShadedSegment(const TransferFunction& tf, FieldGradientSampler sampler,
  void* user, double length, const double* breakpoints, int breakpointCount,
  const VolumeShadingSettings& shading, const GradientOpacityFunction* gradientOpacity,
  const SegmentRay& ray, const ShadedSegmentSettings& settings, const unsigned char* mergeable)
{
  ShadedSegmentResult res;
  if (!(length > 0.0) || !std::isfinite(length) || !sampler || tf.GetNumberOfNodes() == 0)
  {
    return res;
  }
  Context ctx;
  ctx.Tf = &tf;
  ctx.Sampler = sampler;
  ctx.User = user;
  ctx.Shading = &shading;
  ctx.GO = gradientOpacity;
  ctx.Ray = &ray;
  DirectionalShading directional;
  const double toViewer[3] = { -ray.Direction[0], -ray.Direction[1], -ray.Direction[2] };
  if (shading.Shade && PrepareDirectionalShading(shading, toViewer, directional))
  {
    ctx.Directional = &directional;
  }
  ctx.Emission = settings.Emission == EmissionModel::WilhelmsVanGelder;
  ctx.EmissionFactor = tf.GetEmissionFactor();
  ctx.StopUnconverged = settings.StopWhenUnconverged;
  ctx.EvaluationsLeft = std::max(settings.MaxPanels, 1);
  const double tol = settings.Tolerance > 0.0 && std::isfinite(settings.Tolerance) ? settings.Tolerance : 1e-9;
  const double budgetPerLength = tol / length;
  const int maxDepth = std::min(std::max(settings.MaxDepth, 0), StackSize - 2);
  int panelsLeft = std::max(settings.MaxPanels, 1);
  // More pieces than MaxPanels / 2: step over evenly spaced ones of the
  // mergeable breakpoints (file doc).
  const int count = breakpoints ? std::max(breakpointCount, 0) : 0;
  long long numMergeable = 0;
  const int maxPieces = PiecesAllowed(settings);
  for (int i = 0; mergeable && count + 1 > maxPieces && i < count; ++i)
  {
    numMergeable += mergeable[i] != 0;
  }
  const Thinning thinning(count, numMergeable, maxPieces);
  long long rank = 0;
  double prev = 0.0;
  for (int i = 0; i <= count; ++i)
  {
    const double next = i < count ? breakpoints[i] : length;
    if (i < count && numMergeable > 0 && mergeable[i] && !thinning.Keeps(rank++))
    {
      ++res.SkippedBreakpoints;
      continue; // stepped over
    }
    if (i < count && (!(next > prev) || !(next < length)))
    {
      continue; // outside (prev, length) or unsorted
    }
    if (!IntegratePiece(ctx, prev, next, length, budgetPerLength, maxDepth, panelsLeft, res))
    {
      break;
    }
    prev = next;
  }
  res.Samples = ctx.Samples;
  res.Converged = res.Converged && !ctx.Bad;
  return res;
}


ShadedSegmentResult IntegrateShadedPolynomial(const TransferFunction& tf, const Polynomial& s,
  const Polynomial gradient[3], double length, const VolumeShadingSettings& shading,
  const GradientOpacityFunction* gradientOpacity, const SegmentRay& ray,
  const ShadedSegmentSettings& settings)
{
  ShadedSegmentResult res;
  if (!(length > 0.0) || !std::isfinite(length) || !Finite(s) || !Finite(gradient[0]) ||
    !Finite(gradient[1]) || !Finite(gradient[2]) || EffectiveDegree(s) > 8)
  {
    res.Converged = length == 0.0;
    return res;
  }
  const bool constantGradient = EffectiveDegree(gradient[0]) == 0 &&
    EffectiveDegree(gradient[1]) == 0 && EffectiveDegree(gradient[2]) == 0;
  if (EffectiveDegree(s) <= 1 && constantGradient && (!shading.Shade || LightsAreDirectional(shading)))
  {
    const double g[3] = { gradient[0].C[0], gradient[1].C[0], gradient[2].C[0] };
    const double toViewer[3] = { -ray.Direction[0], -ray.Direction[1], -ray.Direction[2] };
    const ShadingTransform shade = ComputeShadingTransform(shading, g, ray.Origin, toViewer);
    const double gamma = gradientOpacity ? gradientOpacity->EvaluateGradient(g) : 1.0;
    IntegrationSettings exact;
    exact.Emission = settings.Emission;
    res.Color = IntegrateLinearScalarShaded(tf, s.C[0], Evaluate(s, length), length, shade, gamma, exact);
    res.ExactPath = true;
    return res;
  }
  std::vector<double> cuts;
  std::vector<unsigned char> smooth;
  int skipped = 0;
  ShadedBreakpoints(tf, s, gradient, gradientOpacity, length, cuts, &smooth,
    PiecesAllowed(settings), &skipped);
  PolynomialField field{ &s, gradient };
  res = IntegrateShadedSegment(tf, &SamplePolynomial, &field, length, cuts.data(),
    static_cast<int>(cuts.size()), shading, gradientOpacity, ray, settings, smooth.data());
  res.SkippedBreakpoints += skipped;
  return res;
}
}
