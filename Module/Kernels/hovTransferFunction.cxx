#include "hovTransferFunction.h"

#include "hovOpacityRefinement.h" // GPU-compatible linearisation

#include <algorithm> // sort, lower_bound, upper_bound
#include <array>     // node values
#include <cmath>     // log1p, isfinite
#include <limits>    // infinity
#include <sstream>   // messages

namespace hov
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();

/// Nodes of a piecewise-linear function with N channels; a jump is two nodes
/// at one X. Values may be +infinity (opaque extinction).
template <int N>
struct Pwl
{
  std::vector<double> X;
  std::vector<std::array<double, N>> V;

  void Append(double x, const std::array<double, N>& v)
  {
    // Drop an exact repeat, and keep at most two nodes (left, right) at one X.
    const size_t n = this->X.size();
    if (n > 0 && this->X[n - 1] == x && this->V[n - 1] == v)
    {
      return;
    }
    if (n > 1 && this->X[n - 1] == x && this->X[n - 2] == x)
    {
      this->V[n - 1] = v;
      return;
    }
    this->X.push_back(x);
    this->V.push_back(v);
  }

  static double Lerp(double v0, double v1, double w)
  {
    if (v0 == Infinity || v1 == Infinity)
    {
      return Infinity;
    }
    return v0 + (v1 - v0) * w;
  }

  /// Left and right limits at x (constant beyond the end nodes).
  void Limits(double x, std::array<double, N>& left, std::array<double, N>& right) const
  {
    const auto lo = std::lower_bound(this->X.begin(), this->X.end(), x);
    const auto hi = std::upper_bound(this->X.begin(), this->X.end(), x);
    if (lo != hi)
    {
      left = this->V[lo - this->X.begin()];
      right = this->V[(hi - this->X.begin()) - 1];
      return;
    }
    const long i = static_cast<long>(hi - this->X.begin()) - 1;
    if (i < 0)
    {
      left = right = this->V.front();
    }
    else if (i + 1 >= static_cast<long>(this->X.size()))
    {
      left = right = this->V.back();
    }
    else
    {
      const double w = (x - this->X[i]) / (this->X[i + 1] - this->X[i]);
      for (int c = 0; c < N; ++c)
      {
        left[c] = Lerp(this->V[i][c], this->V[i + 1][c], w);
      }
      right = left;
    }
  }
};

void Note(std::vector<std::string>* messages, const std::string& text)
{
  if (messages)
  {
    messages->push_back(text);
  }
}

/// Sorted, finite colour nodes (stable, so a jump keeps its left/right order).
Pwl<3> SanitizeColor(const std::vector<ColorNode>& in, std::vector<std::string>* messages)
{
  std::vector<ColorNode> nodes;
  int dropped = 0, clamped = 0;
  for (const ColorNode& n : in)
  {
    if (!std::isfinite(n.X) || !std::isfinite(n.R) || !std::isfinite(n.G) || !std::isfinite(n.B))
    {
      ++dropped;
      continue;
    }
    ColorNode c = n;
    if (c.R < 0.0 || c.G < 0.0 || c.B < 0.0)
    {
      ++clamped;
      c.R = std::max(c.R, 0.0);
      c.G = std::max(c.G, 0.0);
      c.B = std::max(c.B, 0.0);
    }
    nodes.push_back(c);
  }
  if (dropped)
  {
    Note(messages, std::to_string(dropped) + " colour node(s) with NaN/Inf dropped");
  }
  if (clamped)
  {
    Note(messages, std::to_string(clamped) + " colour node(s) with negative components clamped to 0");
  }
  std::stable_sort(nodes.begin(), nodes.end(),
    [](const ColorNode& p, const ColorNode& q) { return p.X < q.X; });
  Pwl<3> out;
  for (const ColorNode& n : nodes)
  {
    out.Append(n.X, { n.R, n.G, n.B });
  }
  if (out.X.empty())
  {
    Note(messages, "no colour nodes: the colour is black");
    out.Append(0.0, { 0.0, 0.0, 0.0 });
  }
  return out;
}

/// Sorted opacity nodes clamped to [0, maxValue] (1 for opacities; +inf for
/// raw extinction, whose values are extinction per unit length).
std::vector<OpacityNode> SanitizeOpacity(
  const std::vector<OpacityNode>& in, double maxValue, std::vector<std::string>* messages)
{
  std::vector<OpacityNode> nodes;
  int dropped = 0, clamped = 0;
  for (const OpacityNode& n : in)
  {
    if (!std::isfinite(n.X) || std::isnan(n.Opacity))
    {
      ++dropped;
      continue;
    }
    OpacityNode o = n;
    if (o.Opacity < 0.0 || o.Opacity > maxValue)
    {
      ++clamped;
      o.Opacity = std::min(std::max(o.Opacity, 0.0), maxValue);
    }
    nodes.push_back(o);
  }
  if (dropped)
  {
    Note(messages, std::to_string(dropped) + " opacity node(s) with a NaN or infinite position or a NaN value dropped");
  }
  if (clamped)
  {
    Note(messages, std::to_string(clamped) + " opacity value(s) outside [0," + (std::isinf(maxValue) ? std::string("inf") : std::to_string(maxValue)) + "] clamped");
  }
  std::stable_sort(nodes.begin(), nodes.end(),
    [](const OpacityNode& p, const OpacityNode& q) { return p.X < q.X; });
  if (nodes.empty())
  {
    Note(messages, "no opacity nodes: the volume is transparent");
    nodes.push_back(OpacityNode{ 0.0, 0.0 });
  }
  return nodes;
}

}

bool TransferFunction::Build(const TransferFunctionSpec& spec, std::vector<std::string>* messages)
{
  this->X.clear();
  this->Nodes.clear();
  this->RefinementNodes = 0;
  this->Semantics = spec.Semantics;

  double unit = spec.UnitDistance;
  if (!(unit > 0.0) || !std::isfinite(unit))
  {
    Note(messages, "unit distance must be positive and finite; using 1");
    unit = 1.0;
  }
  double tol = spec.GPUTolerance;
  if (!(tol >= 1e-14) || !(tol <= 0.5))
  {
    tol = std::min(std::max(std::isnan(tol) ? 1e-4 : tol, 1e-14), 0.5);
    Note(messages, "GPU opacity tolerance clamped to [1e-14, 0.5]");
  }
  this->EmissionFactor = (std::isfinite(spec.EmissionScale) ? spec.EmissionScale : 1.0) / unit;

  const Pwl<3> color = SanitizeColor(spec.Color, messages);
  const bool raw = spec.Semantics == OpacitySemantics::RawExtinction;
  const std::vector<OpacityNode> opacity =
    SanitizeOpacity(spec.Opacity, raw ? Infinity : 1.0, messages);

  // Extinction nodes, refined where the semantics is not linear in a.
  const bool gpuSemantics = spec.Semantics == OpacitySemantics::GPUCompatible;
  const double invUnit = 1.0 / unit;
  auto tauOf = [&](double a) {
    switch (spec.Semantics)
    {
      case OpacitySemantics::GPUCompatible:
        return a >= 1.0 ? Infinity : GPUExtinction(a, 1.0 - a, invUnit);
      case OpacitySemantics::VTKUnstructured:
        return a * invUnit;
      default:
        return a;
    }
  };
  // GPU-compatible intervals of finite extinction (not jumps, not opaque).
  auto refinable = [&](size_t i) {
    const OpacityNode& p = opacity[i];
    const OpacityNode& q = opacity[i + 1];
    return gpuSemantics && p.X != q.X && !(p.Opacity >= 1.0 && q.Opacity >= 1.0);
  };
  std::vector<OpacityInterval> intervals;
  for (size_t i = 0; i + 1 < opacity.size(); ++i)
  {
    if (refinable(i))
    {
      intervals.push_back({ opacity[i].X, opacity[i].Opacity, opacity[i + 1].X, opacity[i + 1].Opacity });
    }
  }
  const int budget = std::min(std::max(spec.RefinementBudget, 0), MaxRefinementNodes);
  const RefinementResult refined = RefineGPUExtinction(intervals, unit, tol, budget);
  this->RefinementNodes = refined.Added;
  if (refined.Exhausted)
  {
    std::ostringstream text;
    text << "GPU-compatible refinement stopped at its budget of " << budget
         << " nodes; worst relative extinction error " << refined.WorstError << " (tolerance "
         << tol << ")";
    Note(messages, text.str());
  }
  Pwl<1> tau;
  tau.Append(opacity[0].X, { tauOf(opacity[0].Opacity) });
  size_t next = 0;
  for (size_t i = 0; i + 1 < opacity.size(); ++i)
  {
    const OpacityNode& p = opacity[i];
    const OpacityNode& q = opacity[i + 1];
    if (!refinable(i))
    {
      // Linear semantics, a jump, or an opaque interval (tau = +inf on both ends).
      tau.Append(p.X, { tauOf(p.Opacity) });
      tau.Append(q.X, { tauOf(q.Opacity) });
      continue;
    }
    // A finite interval: its ends use the clamped extinction even where a = 1
    // (a jump to +inf comes from an opaque neighbour if there is one).
    tau.Append(p.X, { GPUExtinction(p.Opacity, 1.0 - p.Opacity, invUnit) });
    for (const auto& node : refined.Interior[next++])
    {
      tau.Append(node.first, { node.second });
    }
    tau.Append(q.X, { GPUExtinction(q.Opacity, 1.0 - q.Opacity, invUnit) });
  }
  tau.Append(opacity.back().X, { tauOf(opacity.back().Opacity) });

  // Merge: every colour and extinction position, with left/right limits.
  std::vector<double> positions = color.X;
  positions.insert(positions.end(), tau.X.begin(), tau.X.end());
  std::sort(positions.begin(), positions.end());
  positions.erase(std::unique(positions.begin(), positions.end()), positions.end());
  this->AnyExtinction = false;
  for (double x : positions)
  {
    std::array<double, 3> cl, cr;
    std::array<double, 1> tl, tr;
    color.Limits(x, cl, cr);
    tau.Limits(x, tl, tr);
    auto push = [this](double px, const std::array<double, 3>& c, double t) {
      this->X.push_back(px);
      this->Nodes.push_back(Node{ t, c[0], c[1], c[2], 0.0, 0.0, 0.0, 0.0 });
    };
    push(x, cl, tl[0]);
    if (cl != cr || tl != tr)
    {
      push(x, cr, tr[0]);
    }
    this->AnyExtinction = this->AnyExtinction || tl[0] > 0.0 || tr[0] > 0.0;
  }
  this->BuildLookup();
  return true;
}

bool TransferFunction::ZeroExtinctionOver(double lo, double hi) const
{
  const int n = static_cast<int>(this->X.size());
  if (n == 0 || !std::isfinite(lo) || !std::isfinite(hi) || !(lo <= hi))
  {
    return false;
  }
  // Nodes first..last (inclusive) hold [lo, hi] between them or clamp it.
  const int first = std::max(this->FindIntervalDownward(lo), 0);
  const int last = std::min(this->FindIntervalUpward(hi) + 1, n - 1);
  return this->ExtinctionBefore[last + 1] == this->ExtinctionBefore[first];
}

void TransferFunction::BuildLookup()
{
  // Interval lookup grid (4 buckets per node, at most 2^20).
  this->Buckets.clear();
  this->BucketScale = 0.0;
  const size_t n = this->X.size();
  const double span = n > 1 ? this->X[n - 1] - this->X[0] : 0.0;
  if (n > 1 && span > 0.0 && std::isfinite(span))
  {
    const size_t buckets = std::min<size_t>(4 * n, size_t(1) << 20);
    this->BucketScale = buckets / span;
    this->Buckets.resize(buckets);
    size_t k = 0;
    for (size_t b = 0; b < buckets; ++b)
    {
      const double start = this->X[0] + b / this->BucketScale;
      while (k + 1 < n && this->X[k + 1] <= start)
      {
        ++k;
      }
      this->Buckets[b] = static_cast<int>(k);
    }
  }
  // Slopes per interval, so that Evaluate() is one multiply-add per value.
  for (size_t k = 0; k + 1 < this->Nodes.size(); ++k)
  {
    Node& p = this->Nodes[k];
    const Node& q = this->Nodes[k + 1];
    const double width = this->X[k + 1] - this->X[k];
    if (width > 0.0)
    {
      const bool opaque = p.Tau == Infinity || q.Tau == Infinity;
      p.DTau = opaque ? 0.0 : (q.Tau - p.Tau) / width;
      p.DR = (q.R - p.R) / width;
      p.DG = (q.G - p.G) / width;
      p.DB = (q.B - p.B) / width;
      if (opaque)
      {
        p.Tau = Infinity; // both ends of an opaque interval are +inf by construction
      }
    }
  }
  // Nodes a segment integral may step over (IsSmoothNode()): after the slopes.
  // A change of slope d at a node moves the function by at most d w over the
  // wider neighbouring interval w; up to 1e-15 of the table's largest finite
  // value it is the rounding of the slopes (differences of rounded values
  // over w), not a kink. Over a piece of k nodes such changes move it by at
  // most k^2 1e-15 of that (1e-9 for k = 1000).
  double tauScale = 1e-300, colourScale = 1e-300;
  for (const Node& node : this->Nodes)
  {
    tauScale = std::isfinite(node.Tau) ? std::max(tauScale, std::fabs(node.Tau)) : tauScale;
    colourScale = std::max({ colourScale, std::fabs(node.R), std::fabs(node.G), std::fabs(node.B) });
  }
  this->SmoothNodes.assign(this->Nodes.size(), 0);
  for (size_t k = 1; k + 1 < this->Nodes.size(); ++k)
  {
    const Node& a = this->Nodes[k - 1];
    const Node& b = this->Nodes[k];
    const double w = std::max(this->X[k] - this->X[k - 1], this->X[k + 1] - this->X[k]);
    auto same = [w](double u, double v, double scale) {
      return std::fabs(u - v) * w <= 1e-15 * scale;
    };
    this->SmoothNodes[k] = this->X[k - 1] < this->X[k] && this->X[k] < this->X[k + 1] &&
      std::isfinite(a.Tau) && std::isfinite(b.Tau) && std::isfinite(this->Nodes[k + 1].Tau) &&
      (b.DTau >= a.DTau || same(a.DTau, b.DTau, tauScale)) && same(a.DR, b.DR, colourScale) &&
      same(a.DG, b.DG, colourScale) && same(a.DB, b.DB, colourScale);
  }
  // Last: the loop above may set an opaque interval's first tau to +inf.
  this->ExtinctionBefore.assign(this->Nodes.size() + 1, 0);
  for (size_t k = 0; k < this->Nodes.size(); ++k)
  {
    // (NaN is not 0: it counts as extinction.)
    this->ExtinctionBefore[k + 1] = this->ExtinctionBefore[k] + !(this->Nodes[k].Tau == 0.0);
  }
}

}
