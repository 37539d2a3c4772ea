// ShadedBreakpoints (declared in hovShadedSegment.h): the breakpoints of a
// shaded polynomial segment, the mergeable crossings to be stepped over left
// out before they are located.
#include "hovShadedSegment.h"

#include "hovBreakpointThinning.h" // the rule shared with IntegrateShadedSegment
#include "hovGradientOpacity.h"    // its kinks
#include "hovTransferFunction.h"   // the nodes, IsSmoothNode

#include <algorithm> // sort, unique, min, max
#include <cmath>     // isfinite
#include <utility>   // pair
#include <vector>

namespace hov
{
using detail::Thinning;

int ShadedBreakpoints(const TransferFunction& tf, const Polynomial& s, const Polynomial gradient[3],
  const GradientOpacityFunction* gradientOpacity, double length, std::vector<double>& out,
  std::vector<unsigned char>* mergeable, int maxPieces, int* skipped)
{
  out.clear();
  if (mergeable)
  {
    mergeable->clear();
  }
  if (skipped)
  {
    *skipped = 0;
  }
  // With @p mergeable: one flag per breakpoint, kept beside it through the
  // sort. Only t in (0, length) is kept (never a NaN: it would upset the sort).
  std::vector<std::pair<double, unsigned char>> flagged;
  auto add = [&](double t, bool smooth) {
    if (!(t > 0.0 && t < length))
    {
      return;
    }
    if (mergeable)
    {
      flagged.emplace_back(t, smooth ? 1 : 0);
    }
    else
    {
      out.push_back(t);
    }
  };
  if (!(length > 0.0) || !std::isfinite(length))
  {
    return 0;
  }
  double roots[Polynomial::MaxDegree];
  // Gradient-opacity kinks: |g|^2 = kink^2, when |g|^2 fits a Polynomial.
  if (gradientOpacity && !gradientOpacity->IsIdentity() && !gradientOpacity->GetKinks().empty())
  {
    int dg = 0;
    for (int i = 0; i < 3; ++i)
    {
      dg = std::max(dg, EffectiveDegree(gradient[i]));
    }
    if (2 * dg <= Polynomial::MaxDegree)
    {
      Polynomial q;
      q.Degree = 2 * dg;
      for (int i = 0; i < 3; ++i)
      {
        for (int a = 0; a <= dg; ++a)
        {
          for (int b = 0; b <= dg; ++b)
          {
            q.C[a + b] += gradient[i].C[a] * gradient[i].C[b];
          }
        }
      }
      for (double kink : gradientOpacity->GetKinks())
      {
        const int c = FindRoots(q, kink * kink, 0.0, length, roots);
        for (int i = 0; i < c; ++i)
        {
          add(roots[i], false);
        }
      }
    }
  }
  // Monotone runs of s (between the roots of s'), each with the table nodes
  // strictly inside its range of s: [K0, K1), distinct values, in t order
  // (descending k where s decreases).
  struct Run
  {
    double T0, T1, Lo; // Lo: the least s on the run
    int K0, K1;
    bool Up;
  };
  Run runs[Polynomial::MaxDegree + 1];
  const int m = EffectiveDegree(s) >= 2 ? FindRoots(Derivative(s), 0.0, 0.0, length, roots) : 0;
  const std::vector<double>& x = tf.GetNodes();
  const int n = static_cast<int>(x.size());
  long long crossings = 0, smooth = 0;
  double ta = 0.0, sa = Evaluate(s, 0.0);
  for (int r = 0; r <= m; ++r)
  {
    const double tb = r < m ? roots[r] : length;
    const double sb = Evaluate(s, tb);
    const double lo = std::min(sa, sb), hi = std::max(sa, sb);
    Run& run = runs[r];
    run = Run{ ta, tb, lo, std::max(tf.FindIntervalUpward(lo), 0), 0, sb > sa };
    for (run.K1 = run.K0; run.K1 < n && x[run.K1] < hi; ++run.K1)
    {
    }
    for (int k = run.K0; k < run.K1; ++k)
    {
      if (x[k] > lo && (k == 0 || x[k] != x[k - 1]))
      {
        ++crossings;
        smooth += mergeable && tf.IsSmoothNode(k);
      }
    }
    ta = tb;
    sa = sb;
  }
  // Pre-thinned (IntegrateShadedSegment's rule): a stepped-over crossing is
  // never solved for. The count includes the GO kinks added above.
  const long long count = crossings + m + static_cast<long long>(flagged.size() + out.size());
  const Thinning thinning(count, maxPieces > 0 ? smooth : 0, std::max(maxPieces, 1));
  long long rank = 0;
  for (int r = 0; r <= m; ++r)
  {
    const Run& run = runs[r];
    for (int i = 0; i < run.K1 - run.K0; ++i)
    {
      const int k = run.Up ? run.K0 + i : run.K1 - 1 - i;
      if (!(x[k] > run.Lo && (k == 0 || x[k] != x[k - 1])))
      {
        continue;
      }
      const bool isSmooth = mergeable && tf.IsSmoothNode(k);
      if (isSmooth && maxPieces > 0 && !thinning.Keeps(rank++))
      {
        if (skipped)
        {
          ++*skipped;
        }
        continue;
      }
      add(SolveMonotone(s, x[k], run.T0, run.T1), isSmooth);
    }
    if (r < m)
    {
      // An extremum of s: never stepped over. Beyond it s comes back, so a
      // piece across it could hold a narrow bump of tau(s(t)) (s peaking just
      // past a convex node) that no sample sees; with s monotone in every
      // piece, tau convex in s peaks at the piece's ends, which are sampled.
      add(run.T1, false);
    }
  }
  if (mergeable)
  {
    // Sorted by t; of equal t (one kept), smooth only if every one is.
    std::sort(flagged.begin(), flagged.end());
    for (const auto& f : flagged)
    {
      if (!out.empty() && out.back() == f.first)
      {
        mergeable->back() &= f.second;
        continue;
      }
      out.push_back(f.first);
      mergeable->push_back(f.second);
    }
    return static_cast<int>(out.size());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return static_cast<int>(out.size());
}
}
