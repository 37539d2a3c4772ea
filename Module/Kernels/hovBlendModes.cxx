#include "hovBlendModes.h"

#include "hovGaussKronrod15.h" // the 15-point Kronrod rule (exact to degree 22)

#include <algorithm> // min, max, swap
#include <cmath>     // fabs, isfinite, isnan
#include <limits>    // infinity

namespace hov
{
namespace
{
constexpr double Eps = 2.220446049250313e-16;
constexpr double Infinity = std::numeric_limits<double>::infinity();
// First bracket half-width around a computed critical point (relative to
// max(h, |r|)): a few ulp beyond where FindRoots places a simple root.
constexpr double FirstBracketUlps = 16.0;
// Half-width used for a critical point whose sign change cannot be verified
// (an even-multiplicity root of S': not an extremum), relative to h.
constexpr double UnverifiedBracket = 1.0 / 1024.0;

double Clamp01(double v)
{
  return std::isnan(v) ? 0.0 : std::min(std::max(v, 0.0), 1.0);
}

/// s normalised by the data range (0 if the range is empty or not finite).
double Normalised(double s, const BlendSettings& settings)
{
  const double width = settings.ScalarRange[1] - settings.ScalarRange[0];
  if (!(width > 0.0) || !std::isfinite(width))
  {
    return 0.0;
  }
  return (s - settings.ScalarRange[0]) / width;
}

void AverageLimits(const BlendSettings& settings, double& lo, double& hi)
{
  lo = std::isnan(settings.AverageRange[0]) ? -Infinity : settings.AverageRange[0];
  hi = std::isnan(settings.AverageRange[1]) ? Infinity : settings.AverageRange[1];
  if (hi < lo)
  {
    std::swap(lo, hi); // as vtkOpenGLGPUVolumeRayCastMapper does
  }
}

/// a(s) sn(s) on table interval k (the raw table's Tau is the opacity).
double AverageIntegrand(const TransferFunction& table, int k, double s, const BlendSettings& settings)
{
  SegmentEnd v;
  table.Evaluate(k, s, false, v);
  return Clamp01(v.Tau) * Normalised(s, settings);
}

/// The 15-point Kronrod rule on [u0, u1].
template <class F>
double Kronrod15(const F& f, double u0, double u1)
{
  const double half = 0.5 * (u1 - u0);
  const double mid = 0.5 * (u0 + u1);
  double sum = detail::WGK[7] * f(mid);
  for (int i = 0; i < 7; ++i)
  {
    const double d = half * detail::XGK[i];
    sum += detail::WGK[i] * (f(mid - d) + f(mid + d));
  }
  return sum * half;
}

int SignOf(BlendMode mode)
{
  return mode == BlendMode::MinimumIntensity ? -1 : 1;
}

bool WantsExtremum(BlendMode mode)
{
  return mode == BlendMode::MaximumIntensity || mode == BlendMode::MinimumIntensity;
}

void UpdateExtremum(RayBlendState& state, int sign, double value, double t, double bound)
{
  if (!state.Found || sign * value > sign * state.Value || (value == state.Value && t < state.T))
  {
    state.Value = value;
    state.T = t;
  }
  // The max (min) is 1-Lipschitz in the sup norm: every segment's bound counts.
  state.ErrorBound = std::max(state.ErrorBound, bound);
  state.Found = true;
}

bool FinitePolynomial(const Polynomial& s)
{
  const int n = std::min(std::max(s.Degree, 0), Polynomial::MaxDegree);
  for (int i = 0; i <= n; ++i)
  {
    if (!std::isfinite(s.C[i]))
    {
      return false;
    }
  }
  return true;
}

/// Half-width d of a verified bracket of the root of S' near @p r (file doc).
double BracketCriticalPoint(const Polynomial& ds, double r, double h)
{
  for (double d = FirstBracketUlps * Eps * std::max(h, std::fabs(r)); d <= h; d *= 2.0)
  {
    const double lo = std::max(0.0, r - d), hi = std::min(h, r + d);
    double e0 = 0.0, e1 = 0.0;
    const double v0 = EvaluateCompensated(ds, lo, 0.0, &e0);
    const double v1 = EvaluateCompensated(ds, hi, 0.0, &e1);
    if ((v0 > e0 && v1 < -e1) || (v0 < -e0 && v1 > e1))
    {
      return d;
    }
  }
  return UnverifiedBracket * h;
}

/// Critical points of S in [0, h] (sorted), their number.
int CriticalPoints(const Polynomial& s, double h, double* roots)
{
  if (EffectiveDegree(s) < 2)
  {
    return 0;
  }
  return FindRoots(Derivative(s), 0.0, 0.0, h, roots);
}

/**
 * Average-mode integral over one monotone run [ta, tb] of S (values sa, sb):
 * the sub-run inside [lo, hi], split at every table node crossed.
 */
void AverageOnRun(RayBlendState& state, const BlendSettings& settings, const TransferFunction& table,
  const Polynomial& s, double ta, double tb, double sa, double sb)
{
  double lo, hi;
  AverageLimits(settings, lo, hi);
  const bool up = sb >= sa;
  const double sMin = up ? sa : sb, sMax = up ? sb : sa;
  if (sMax < lo || sMin > hi || !(tb > ta))
  {
    return;
  }
  // The sub-run where lo <= S <= hi: ends moved onto the limits crossed.
  double ua = ta, ub = tb, va = sa, vb = sb;
  const double enter = up ? lo : hi, leave = up ? hi : lo;
  if (up ? sa < lo : sa > hi)
  {
    ua = SolveMonotone(s, enter, ta, tb);
    va = enter;
  }
  if (up ? sb > hi : sb < lo)
  {
    ub = SolveMonotone(s, leave, ua, tb);
    vb = leave;
  }
  if (!(ub > ua))
  {
    return;
  }
  state.InRangeLength += ub - ua;
  const std::vector<double>& nodes = table.GetNodes();
  const int n = static_cast<int>(nodes.size());
  int k = up ? table.FindIntervalUpward(va) : table.FindIntervalDownward(va);
  double tPrev = ua;
  while (true)
  {
    double tNext = ub;
    bool last = true;
    if (up && k + 1 < n && nodes[k + 1] < vb)
    {
      tNext = SolveMonotone(s, nodes[k + 1], tPrev, ub);
      last = false;
    }
    else if (!up && k >= 0 && nodes[k] > vb)
    {
      tNext = SolveMonotone(s, nodes[k], tPrev, ub);
      last = false;
    }
    if (tNext > tPrev)
    {
      const int interval = k;
      state.WeightedIntegral += Kronrod15(
        [&](double t) { return AverageIntegrand(table, interval, Evaluate(s, t), settings); },
        tPrev, tNext);
    }
    if (last)
    {
      break;
    }
    tPrev = std::max(tPrev, tNext);
    k += up ? 1 : -1;
  }
}
}

TransferFunctionSpec BlendModeTableSpec(const TransferFunctionSpec& spec)
{
  TransferFunctionSpec raw = spec;
  raw.Semantics = OpacitySemantics::VTKUnstructured;
  raw.UnitDistance = 1.0;
  raw.EmissionScale = 1.0;
  return raw;
}

bool PolynomialExtremum(
  const Polynomial& s, double h, int sign, double& value, double& where, double& bound)
{
  if (!(h >= 0.0) || !std::isfinite(h) || !FinitePolynomial(s))
  {
    return false;
  }
  sign = sign < 0 ? -1 : 1;
  bool first = true;
  bound = 0.0;
  auto consider = [&](double t, double extra) {
    double e = 0.0;
    const double v = EvaluateCompensated(s, t, 0.0, &e);
    if (first || sign * v > sign * value || (v == value && t < where))
    {
      value = v;
      where = t;
      first = false;
    }
    bound = std::max(bound, e + extra);
  };
  consider(0.0, 0.0);
  consider(h, 0.0);
  double roots[Polynomial::MaxDegree];
  const int m = CriticalPoints(s, h, roots);
  if (m > 0)
  {
    const Polynomial ds = Derivative(s);
    const int n = EffectiveDegree(s);
    double m2 = 0.0, hk = 1.0; // M2 = sum k (k-1) |c_k| h^(k-2) >= max |S''|
    for (int k = 2; k <= n; ++k)
    {
      m2 += k * (k - 1) * std::fabs(s.C[k]) * hk;
      hk *= h;
    }
    for (int i = 0; i < m; ++i)
    {
      const double d = BracketCriticalPoint(ds, roots[i], h);
      consider(roots[i], 0.5 * m2 * d * d);
    }
  }
  return true;
}

void AccumulateLinearSegment(RayBlendState& state, const BlendSettings& settings,
  const TransferFunction& table, double tFront, double length, double sFront, double sBack)
{
  if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(tFront) ||
    !std::isfinite(sFront) || !std::isfinite(sBack))
  {
    ++state.SkippedSegments;
    return;
  }
  ++state.Segments;
  state.Length += length;
  state.ScalarIntegral += (0.5 * sFront + 0.5 * sBack) * length;
  if (WantsExtremum(settings.Mode))
  {
    const int sign = SignOf(settings.Mode);
    const bool front = sign * sFront >= sign * sBack; // ties: the front end
    UpdateExtremum(state, sign, front ? sFront : sBack, front ? tFront : tFront + length, 0.0);
  }
  else
  {
    state.Found = true;
  }
  if (settings.Mode != BlendMode::AverageIntensity || table.GetNumberOfNodes() == 0)
  {
    return;
  }
  double lo, hi;
  AverageLimits(settings, lo, hi);
  const double ds = sBack - sFront;
  if (ds == 0.0 || !std::isfinite(ds))
  {
    const double s = 0.5 * sFront + 0.5 * sBack;
    if (lo <= s && s <= hi)
    {
      state.InRangeLength += length;
      state.WeightedIntegral +=
        length * AverageIntegrand(table, table.FindIntervalUpward(s), s, settings);
    }
    return;
  }
  // Fractions x of the segment where lo <= s <= hi; s(x) = sFront + ds x.
  const bool up = ds > 0.0;
  const double sA = up ? std::max(sFront, lo) : std::min(sFront, hi);
  const double sB = up ? std::min(sBack, hi) : std::max(sBack, lo);
  if (up ? !(sA < sB) : !(sA > sB))
  {
    return;
  }
  auto fraction = [&](double s) { return std::min(std::max((s - sFront) / ds, 0.0), 1.0); };
  const double x0 = sA == sFront ? 0.0 : fraction(sA);
  const double x1 = sB == sBack ? 1.0 : fraction(sB);
  state.InRangeLength += length * (x1 - x0);
  const std::vector<double>& nodes = table.GetNodes();
  const int n = static_cast<int>(nodes.size());
  int k = up ? table.FindIntervalUpward(sA) : table.FindIntervalDownward(sA);
  double xPrev = x0, sPrev = sA;
  while (true)
  {
    double sNext = sB, xNext = x1;
    bool last = true;
    if (up && k + 1 < n && nodes[k + 1] < sB)
    {
      sNext = nodes[k + 1];
      last = false;
    }
    else if (!up && k >= 0 && nodes[k] > sB)
    {
      sNext = nodes[k];
      last = false;
    }
    if (!last)
    {
      xNext = std::min(std::max(fraction(sNext), xPrev), x1);
    }
    const double w = length * (xNext - xPrev);
    if (w > 0.0)
    {
      // a(s) sn(s) is quadratic in x on one interval: Simpson's rule is exact.
      const double f0 = AverageIntegrand(table, k, sPrev, settings);
      const double fm = AverageIntegrand(table, k, 0.5 * sPrev + 0.5 * sNext, settings);
      const double f1 = AverageIntegrand(table, k, sNext, settings);
      state.WeightedIntegral += w * (f0 + 4.0 * fm + f1) / 6.0;
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

void AccumulatePolynomialSegment(RayBlendState& state, const BlendSettings& settings,
  const TransferFunction& table, double tStart, double length, const Polynomial& s,
  double errorBound)
{
  if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(tStart) ||
    !FinitePolynomial(s) || !(errorBound >= 0.0) || !std::isfinite(errorBound))
  {
    ++state.SkippedSegments;
    return;
  }
  if (EffectiveDegree(s) <= 1)
  {
    // Affine along the ray: the exact linear path (plus the restriction error).
    AccumulateLinearSegment(state, settings, table, tStart, length, s.C[0], Evaluate(s, length));
    state.ErrorBound = std::max(state.ErrorBound, errorBound);
    return;
  }
  ++state.Segments;
  state.Length += length;
  state.ScalarIntegral += Kronrod15([&](double t) { return Evaluate(s, t); }, 0.0, length);
  if (WantsExtremum(settings.Mode))
  {
    const int sign = SignOf(settings.Mode);
    double value = 0.0, where = 0.0, bound = 0.0;
    PolynomialExtremum(s, length, sign, value, where, bound);
    UpdateExtremum(state, sign, value, tStart + where, bound + errorBound);
  }
  state.Found = true;
  if (settings.Mode != BlendMode::AverageIntensity || table.GetNumberOfNodes() == 0)
  {
    return;
  }
  // Monotone runs between the critical points.
  double roots[Polynomial::MaxDegree];
  const int m = CriticalPoints(s, length, roots);
  double ta = 0.0, sa = s.C[0];
  for (int i = 0; i <= m; ++i)
  {
    const double tb = i < m ? roots[i] : length;
    const double sb = Evaluate(s, tb);
    AverageOnRun(state, settings, table, s, ta, tb, sa, sb);
    ta = tb;
    sa = sb;
  }
}

void MergeBlendStates(RayBlendState& into, const RayBlendState& other, const BlendSettings& settings)
{
  if (other.Found)
  {
    if (WantsExtremum(settings.Mode))
    {
      UpdateExtremum(into, SignOf(settings.Mode), other.Value, other.T, other.ErrorBound);
    }
    into.Found = true;
  }
  into.WeightedIntegral += other.WeightedIntegral;
  into.InRangeLength += other.InRangeLength;
  into.ScalarIntegral += other.ScalarIntegral;
  into.Length += other.Length;
  into.Segments += other.Segments;
  into.SkippedSegments += other.SkippedSegments;
}

RGBA ResolveBlend(const RayBlendState& state, const BlendSettings& settings, const TransferFunction& table)
{
  RGBA out;
  if (!state.Found)
  {
    return out;
  }
  if (WantsExtremum(settings.Mode) && table.GetNumberOfNodes() > 0)
  {
    SegmentEnd v;
    table.Evaluate(table.FindIntervalUpward(state.Value), state.Value, false, v);
    const double a = Clamp01(v.Tau);
    out.R = Clamp01(v.Color[0]) * a;
    out.G = Clamp01(v.Color[1]) * a;
    out.B = Clamp01(v.Color[2]) * a;
    out.A = a;
  }
  else if (settings.Mode == BlendMode::AverageIntensity && state.InRangeLength > 0.0)
  {
    const double v = Clamp01(state.WeightedIntegral / state.InRangeLength);
    out.R = out.G = out.B = v;
    out.A = 1.0;
  }
  return out;
}

double MeanScalar(const RayBlendState& state)
{
  return state.Length > 0.0 ? state.ScalarIntegral / state.Length : 0.0;
}
}
