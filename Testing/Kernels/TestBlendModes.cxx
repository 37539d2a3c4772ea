// Tests of hovBlendModes: MIP, MinIP and average intensity (VTK's
// definitions) on analytic scenes -- a ray through one linear tetrahedron, a
// quadratic tetrahedron holding a field with a known interior maximum --
// against closed forms and long double references (hovFeatureTestReference.h:
// raw-node transfer functions, tanh-sinh, bisection; Boost's Brent minimiser
// for polynomial extrema); order independence, composition, branch continuity
// and degenerate input.

#include "hovBlendModes.h"

#include "hovCellRestriction.h"
#include "hovTransferFunction.h"

#include "hovFeatureTestReference.h"
#include "hovKernelTestTolerances.h"
#include "hovKernelTestUtilities.h"

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/tools/minima.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using hovtest::LD;
using hovtest::Str;
using hovtest::Tolerances;
using hovtest::Worst;

namespace
{
hov::TransferFunctionSpec RandomSpec(std::mt19937_64& rng, int colorNodes, int opacityNodes)
{
  hov::TransferFunctionSpec spec;
  std::vector<double> xc, xo;
  for (int i = 0; i < colorNodes; ++i)
  {
    xc.push_back(hovtest::Uniform(rng, -0.2, 1.2));
  }
  for (int i = 0; i < opacityNodes; ++i)
  {
    xo.push_back(hovtest::Uniform(rng, -0.2, 1.2));
  }
  std::sort(xc.begin(), xc.end());
  std::sort(xo.begin(), xo.end());
  for (double x : xc)
  {
    spec.Color.push_back({ x, hovtest::Uniform(rng, 0, 1), hovtest::Uniform(rng, 0, 1),
      hovtest::Uniform(rng, 0, 1) });
  }
  for (double x : xo)
  {
    spec.Opacity.push_back({ x, hovtest::Uniform(rng, 0, 1) });
  }
  // The blend modes ignore these (BlendModeTableSpec): set to something else.
  spec.Semantics = hov::OpacitySemantics::GPUCompatible;
  spec.UnitDistance = 0.37;
  return spec;
}

hov::TransferFunction RawTable(const hov::TransferFunctionSpec& spec)
{
  hov::TransferFunction tf;
  tf.Build(hov::BlendModeTableSpec(spec));
  return tf;
}

/// Reference of VTK's average: int_I a(s) sn dt and |I| for s(t) on [0, L].
void ReferenceAverage(const std::function<LD(LD)>& s, LD length, const hovtest::RefRawTransfer& raw,
  const hov::BlendSettings& bs, LD& weighted, LD& measure)
{
  LD lo = bs.AverageRange[0], hi = bs.AverageRange[1];
  if (hi < lo)
  {
    std::swap(lo, hi);
  }
  std::vector<LD> cuts{ 0.0L, length };
  std::vector<LD> levels{ lo, hi };
  levels.insert(levels.end(), raw.A.X.begin(), raw.A.X.end());
  for (LD level : levels)
  {
    for (LD t : hovtest::LevelCrossings(s, level, 0.0L, length))
    {
      cuts.push_back(t);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  static boost::math::quadrature::tanh_sinh<LD> ts;
  weighted = measure = 0.0L;
  const LD r0 = bs.ScalarRange[0], width = static_cast<LD>(bs.ScalarRange[1]) - r0;
  for (size_t i = 0; i + 1 < cuts.size(); ++i)
  {
    const LD a = cuts[i], b = cuts[i + 1];
    const LD sm = s(0.5L * (a + b));
    if (!(b > a) || sm < lo || sm > hi)
    {
      continue;
    }
    measure += b - a;
    weighted += ts.integrate([&](LD t) { const LD v = s(t); return raw.A(v) * (v - r0) / width; }, a, b, 1e-18L);
  }
}

/// Ray / tetrahedron in long double: barycentric lambda_i(t) = alpha_i + beta_i t.
struct RefTetRay
{
  LD Alpha[4], Beta[4];
  LD T0 = 0, T1 = -1;
};

RefTetRay ClipTet(const double p[4][3], const double o[3], const double d[3])
{
  // lambda_{1..3} = E^-1 (x - p0) with E = [p1-p0 | p2-p0 | p3-p0].
  LD e[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      e[r][c] = static_cast<LD>(p[c + 1][r]) - p[0][r];
    }
  }
  const LD det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
    e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  LD inv[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
      inv[r][c] = (e[r1][c1] * e[r2][c2] - e[r1][c2] * e[r2][c1]) / det;
    }
  }
  RefTetRay out;
  LD sa = 0, sb = 0;
  for (int i = 0; i < 3; ++i)
  {
    out.Alpha[i + 1] = 0;
    out.Beta[i + 1] = 0;
    for (int k = 0; k < 3; ++k)
    {
      out.Alpha[i + 1] += inv[i][k] * (static_cast<LD>(o[k]) - p[0][k]);
      out.Beta[i + 1] += inv[i][k] * static_cast<LD>(d[k]);
    }
    sa += out.Alpha[i + 1];
    sb += out.Beta[i + 1];
  }
  out.Alpha[0] = 1 - sa;
  out.Beta[0] = -sb;
  LD t0 = -1e30L, t1 = 1e30L;
  for (int i = 0; i < 4; ++i)
  {
    if (out.Beta[i] > 0)
    {
      t0 = std::max(t0, -out.Alpha[i] / out.Beta[i]);
    }
    else if (out.Beta[i] < 0)
    {
      t1 = std::min(t1, -out.Alpha[i] / out.Beta[i]);
    }
    else if (out.Alpha[i] < 0)
    {
      t1 = -1e30L;
    }
  }
  out.T0 = t0;
  out.T1 = t1;
  return out;
}

/// A random tetrahedron of positive volume around the unit cube, and a ray through it.
void RandomTetAndRay(std::mt19937_64& rng, double p[4][3], double o[3], double d[3], RefTetRay& clip)
{
  while (true)
  {
    for (auto& v : std::vector<double*>{ p[0], p[1], p[2], p[3] })
    {
      for (int k = 0; k < 3; ++k)
      {
        v[k] = hovtest::Uniform(rng, 0, 1);
      }
    }
    double c[3] = { 0, 0, 0 };
    for (int i = 0; i < 4; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        c[k] += 0.25 * p[i][k];
      }
    }
    std::normal_distribution<double> nd;
    double l = 0;
    for (int k = 0; k < 3; ++k)
    {
      d[k] = nd(rng);
      l += d[k] * d[k];
    }
    for (int k = 0; k < 3; ++k)
    {
      d[k] /= std::sqrt(l);
      o[k] = c[k] - 2.0 * d[k] + 0.05 * nd(rng);
    }
    clip = ClipTet(p, o, d);
    if (clip.T1 - clip.T0 > 1e-3)
    {
      return;
    }
  }
}
}

TEST(BlendModes, LinearTetrahedronAgainstClosedFormsAndReference)
{
  std::mt19937_64 rng(1901);
  Worst mipErr, minErr, pixelErr, avgErr, meanErr;
  for (int trial = 0; trial < 300; ++trial)
  {
    double p[4][3], o[3], d[3], sNode[4];
    RefTetRay clip;
    RandomTetAndRay(rng, p, o, d, clip);
    for (double& v : sNode)
    {
      v = hovtest::Uniform(rng, -0.1, 1.1);
    }
    auto sRef = [&](LD t) {
      LD v = 0;
      for (int i = 0; i < 4; ++i)
      {
        v += sNode[i] * (clip.Alpha[i] + clip.Beta[i] * t);
      }
      return v;
    };
    const hov::TransferFunctionSpec spec = RandomSpec(rng, 1 + trial % 5, 1 + trial % 7);
    const hov::TransferFunction table = RawTable(spec);
    const hovtest::RefRawTransfer raw(spec);
    const double t0 = static_cast<double>(clip.T0), t1 = static_cast<double>(clip.T1);
    const double sF = static_cast<double>(sRef(clip.T0)), sB = static_cast<double>(sRef(clip.T1));
    const std::string where = "trial " + std::to_string(trial) + " sF=" + Str(sF) + " sB=" + Str(sB);
    for (hov::BlendMode mode : { hov::BlendMode::MaximumIntensity, hov::BlendMode::MinimumIntensity,
           hov::BlendMode::AverageIntensity })
    {
      hov::BlendSettings bs;
      bs.Mode = mode;
      bs.ScalarRange[0] = -0.1;
      bs.ScalarRange[1] = 1.1;
      if (trial % 3 == 1)
      {
        bs.AverageRange[0] = 0.7; // reversed on purpose: VTK swaps it
        bs.AverageRange[1] = 0.25;
      }
      hov::RayBlendState st;
      hov::AccumulateLinearSegment(st, bs, table, t0, t1 - t0, sF, sB);
      const hov::RGBA px = hov::ResolveBlend(st, bs, table);
      ASSERT_TRUE(hovtest::AllFinite(px)) << where;
      if (mode == hov::BlendMode::AverageIntensity)
      {
        LD weighted, measure;
        auto sLocal = [&](LD u) { return sRef(clip.T0 + u); };
        ReferenceAverage(sLocal, clip.T1 - clip.T0, raw, bs, weighted, measure);
        avgErr.Add(std::fabs(st.WeightedIntegral - weighted), where);
        avgErr.Add(std::fabs(st.InRangeLength - measure), where);
        if (measure > 0)
        {
          const LD v = std::min(std::max(weighted / measure, 0.0L), 1.0L);
          pixelErr.Add(std::fabs(px.R - v) + std::fabs(px.A - 1.0), where);
        }
        else
        {
          pixelErr.Add(std::fabs(px.A), where);
        }
        const LD meanRef = 0.5L * (sRef(clip.T0) + sRef(clip.T1));
        meanErr.Add(std::fabs(hov::MeanScalar(st) - meanRef), where);
        continue;
      }
      const bool isMax = mode == hov::BlendMode::MaximumIntensity;
      const LD ext = isMax ? std::max(sRef(clip.T0), sRef(clip.T1)) : std::min(sRef(clip.T0), sRef(clip.T1));
      (isMax ? mipErr : minErr).Add(std::fabs(st.Value - ext), where);
      EXPECT_EQ(st.ErrorBound, 0.0);
      LD c[3];
      raw.Color(st.Value, c);
      const LD a = std::min(std::max(raw.A(st.Value), 0.0L), 1.0L);
      pixelErr.Add(std::max({ std::fabs(px.R - c[0] * a), std::fabs(px.G - c[1] * a),
                     std::fabs(px.B - c[2] * a), std::fabs(px.A - a) }),
        where);
    }
  }
  hovtest::ReportMeasured("BlendModes.LinearMIP", mipErr);
  hovtest::ReportMeasured("BlendModes.LinearMinIP", minErr);
  hovtest::ReportMeasured("BlendModes.LinearPixel", pixelErr);
  hovtest::ReportMeasured("BlendModes.LinearAverageIntegrals", avgErr);
  hovtest::ReportMeasured("BlendModes.LinearMean", meanErr);
  EXPECT_LE(mipErr.Value, Tolerances.BlendEndValueAbs) << mipErr.Where;
  EXPECT_LE(minErr.Value, Tolerances.BlendEndValueAbs) << minErr.Where;
  EXPECT_LE(pixelErr.Value, Tolerances.BlendPixelAbs) << pixelErr.Where;
  EXPECT_LE(avgErr.Value, Tolerances.BlendAverageAbs) << avgErr.Where;
  EXPECT_LE(meanErr.Value, Tolerances.BlendAverageAbs) << meanErr.Where;
}

namespace
{
/// Quadratic tetrahedron (straight edges) with nodes in VTK order.
void QuadraticTetNodes(const double p[4][3], double nodes[30])
{
  const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
  for (int i = 0; i < 4; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      nodes[3 * i + k] = p[i][k];
    }
  }
  for (int e = 0; e < 6; ++e)
  {
    for (int k = 0; k < 3; ++k)
    {
      nodes[3 * (4 + e) + k] = 0.5 * (p[edges[e][0]][k] + p[edges[e][1]][k]);
    }
  }
}
}

TEST(BlendModes, QuadraticFieldWithKnownInteriorMaximum)
{
  // s(x) = 1 - |x - c|^2 is reproduced exactly by a quadratic tetrahedron; c
  // is placed at distance delta from the ray, its foot inside the segment:
  // the maximum along the ray is 1 - delta^2 at t* = d . (c - o).
  std::mt19937_64 rng(1902);
  Worst valueErr, whereErr, boundRatio, avgErr;
  int tested = 0;
  for (int trial = 0; tested < 200 && trial < 2000; ++trial)
  {
    double p[4][3], o[3], d[3];
    RefTetRay clip;
    RandomTetAndRay(rng, p, o, d, clip);
    const LD t0 = clip.T0, t1 = clip.T1;
    const LD tm = t0 + (t1 - t0) * hovtest::Uniform(rng, 0.2, 0.8);
    // A unit vector perpendicular to d.
    double q[3] = { d[1], -d[0], 0.0 };
    if (std::fabs(d[2]) > 0.9)
    {
      q[0] = 0.0;
      q[1] = d[2];
      q[2] = -d[1];
    }
    const double ql = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    const double delta = hovtest::Uniform(rng, 0.0, 0.3);
    double c[3];
    for (int k = 0; k < 3; ++k)
    {
      c[k] = static_cast<double>(o[k] + tm * d[k]) + delta * q[k] / ql;
    }
    double nodes[30], s[10];
    QuadraticTetNodes(p, nodes);
    for (int i = 0; i < 10; ++i)
    {
      double r2 = 0;
      for (int k = 0; k < 3; ++k)
      {
        r2 += (nodes[3 * i + k] - c[k]) * (nodes[3 * i + k] - c[k]);
      }
      s[i] = 1.0 - r2;
    }
    auto sRef = [&](LD t) {
      LD r2 = 0;
      for (int k = 0; k < 3; ++k)
      {
        const LD x = o[k] + t * d[k] - c[k];
        r2 += x * x;
      }
      return 1.0L - r2;
    };
    LD tStar = 0;
    for (int k = 0; k < 3; ++k)
    {
      tStar += static_cast<LD>(d[k]) * (static_cast<LD>(c[k]) - o[k]);
    }
    std::vector<hov::RestrictedPiece> pieces;
    hov::RestrictCellScalar(hov::CellShape::QuadraticTetra, nodes, s, o, d,
      static_cast<double>(t0), static_cast<double>(t1), hov::CellRestrictionSettings(), pieces);
    ASSERT_EQ(pieces.size(), 1u);
    const hov::TransferFunctionSpec spec = RandomSpec(rng, 3, 4);
    const hov::TransferFunction table = RawTable(spec);
    const std::string where = "trial " + std::to_string(trial) + " delta=" + Str(delta);
    hov::BlendSettings bs;
    bs.ScalarRange[0] = 0.0;
    bs.ScalarRange[1] = 1.0;
    hov::RayBlendState mip, avg;
    for (const auto& piece : pieces)
    {
      hov::AccumulatePolynomialSegment(mip, bs, table, piece.T0, piece.T1 - piece.T0, piece.S, piece.ErrorBound);
    }
    const LD truth = sRef(tStar);
    const double err = static_cast<double>(std::fabs(mip.Value - truth));
    valueErr.Add(err, where);
    whereErr.Add(static_cast<double>(std::fabs(mip.T - tStar)), where);
    EXPECT_LE(err, mip.ErrorBound + 1e-18) << where;
    boundRatio.Add(mip.ErrorBound / std::max(err, 1e-17), where);
    bs.Mode = hov::BlendMode::AverageIntensity;
    bs.AverageRange[0] = 0.5;
    for (const auto& piece : pieces)
    {
      hov::AccumulatePolynomialSegment(avg, bs, table, piece.T0, piece.T1 - piece.T0, piece.S, piece.ErrorBound);
    }
    LD weighted, measure;
    const hovtest::RefRawTransfer raw(spec);
    ReferenceAverage([&](LD u) { return sRef(t0 + u); }, t1 - t0, raw, bs, weighted, measure);
    avgErr.Add(static_cast<double>(std::max(std::fabs(avg.WeightedIntegral - weighted),
                 std::fabs(avg.InRangeLength - measure))),
      where);
    ++tested;
  }
  hovtest::ReportMeasured("BlendModes.QuadraticInteriorMaxValue", valueErr);
  hovtest::ReportMeasured("BlendModes.QuadraticInteriorMaxLocation", whereErr);
  hovtest::ReportMeasured("BlendModes.QuadraticBoundOverError", boundRatio);
  hovtest::ReportMeasured("BlendModes.QuadraticAverageIntegrals", avgErr);
  EXPECT_EQ(tested, 200);
  EXPECT_LE(valueErr.Value, Tolerances.BlendPolynomialAbs) << valueErr.Where;
  EXPECT_LE(whereErr.Value, Tolerances.BlendLocationAbs) << whereErr.Where;
  EXPECT_LE(avgErr.Value, Tolerances.BlendAverageAbs) << avgErr.Where;
}

TEST(BlendModes, PolynomialExtremumAgainstBrent)
{
  std::mt19937_64 rng(1903);
  Worst relErr, violations;
  int count = 0;
  for (int degree = 2; degree <= 8; ++degree)
  {
    for (int trial = 0; trial < 150; ++trial)
    {
      hov::Polynomial s;
      s.Degree = degree;
      const double h = hovtest::LogUniform(rng, 0.05, 5.0);
      for (int k = 0; k <= degree; ++k)
      {
        s.C[k] = hovtest::Uniform(rng, -1, 1) / std::pow(h, k); // O(1) on [0, h]
      }
      LD scale = 0;
      for (int k = 0; k <= degree; ++k)
      {
        scale += std::fabs(s.C[k]) * std::pow(static_cast<LD>(h), k);
      }
      auto p = [&](LD t) {
        LD r = s.C[degree];
        for (int k = degree - 1; k >= 0; --k)
        {
          r = r * t + s.C[k];
        }
        return r;
      };
      for (int sign : { 1, -1 })
      {
        // Reference: dense samples, then Brent (64 bits) around the best.
        const int m = 4000;
        int best = 0;
        for (int i = 1; i <= m; ++i)
        {
          if (sign * p(h * static_cast<LD>(i) / m) > sign * p(h * static_cast<LD>(best) / m))
          {
            best = i;
          }
        }
        LD ref = p(h * static_cast<LD>(best) / m);
        if (best > 0 && best < m)
        {
          const auto r = boost::math::tools::brent_find_minima(
            [&](LD t) { return -sign * p(t); }, h * static_cast<LD>(best - 1) / m,
            h * static_cast<LD>(best + 1) / m, 64);
          ref = sign > 0 ? std::max(ref, -r.second) : std::min(ref, r.second);
        }
        double value, where, bound;
        ASSERT_TRUE(hov::PolynomialExtremum(s, h, sign, value, where, bound));
        const std::string at = "degree " + std::to_string(degree) + " trial " + std::to_string(trial) +
          " sign " + std::to_string(sign) + " h=" + Str(h);
        const double err = static_cast<double>(std::fabs(value - ref));
        relErr.Add(err / static_cast<double>(scale), at);
        // The bound must hold (the long double reference itself: ~1e-18 scale).
        violations.Add(err - bound - 1e-17 * static_cast<double>(scale), at);
        EXPECT_GE(where, 0.0);
        EXPECT_LE(where, h);
        EXPECT_NEAR(value, static_cast<double>(p(where)), bound + 1e-15 * static_cast<double>(scale)) << at;
        ++count;
      }
    }
  }
  hovtest::ReportMeasured("BlendModes.ExtremumVsBrentRel", relErr);
  hovtest::ReportMeasured("BlendModes.ExtremumBoundViolation", violations);
  EXPECT_LE(relErr.Value, Tolerances.BlendPolynomialRel) << relErr.Where;
  EXPECT_LE(violations.Value, 0.0) << violations.Where;
  EXPECT_EQ(count, 7 * 150 * 2);
}

TEST(BlendModes, OrderIndependenceAndComposition)
{
  std::mt19937_64 rng(1904);
  const hov::TransferFunctionSpec spec = RandomSpec(rng, 4, 6);
  const hov::TransferFunction table = RawTable(spec);
  Worst sumErr, splitErr;
  for (int trial = 0; trial < 100; ++trial)
  {
    struct Seg
    {
      double T, L, SF, SB;
      hov::Polynomial P;
      bool Poly;
    };
    std::vector<Seg> segs;
    double t = 0;
    for (int i = 0; i < 8; ++i)
    {
      Seg g;
      g.T = t;
      g.L = hovtest::Uniform(rng, 0.01, 0.5);
      g.SF = hovtest::Uniform(rng, -0.2, 1.2);
      g.SB = hovtest::Uniform(rng, -0.2, 1.2);
      g.Poly = i % 2 == 1;
      g.P = hov::Polynomial::FromCoefficients({ g.SF, hovtest::Uniform(rng, -2, 2), hovtest::Uniform(rng, -4, 4) });
      segs.push_back(g);
      t += g.L;
    }
    for (hov::BlendMode mode : { hov::BlendMode::MaximumIntensity, hov::BlendMode::MinimumIntensity,
           hov::BlendMode::AverageIntensity })
    {
      hov::BlendSettings bs;
      bs.Mode = mode;
      bs.AverageRange[0] = 0.1;
      bs.AverageRange[1] = 0.9;
      auto run = [&](const std::vector<Seg>& order) {
        hov::RayBlendState st;
        for (const Seg& g : order)
        {
          if (g.Poly)
          {
            hov::AccumulatePolynomialSegment(st, bs, table, g.T, g.L, g.P);
          }
          else
          {
            hov::AccumulateLinearSegment(st, bs, table, g.T, g.L, g.SF, g.SB);
          }
        }
        return st;
      };
      const hov::RayBlendState a = run(segs);
      std::vector<Seg> shuffled = segs;
      std::shuffle(shuffled.begin(), shuffled.end(), rng);
      const hov::RayBlendState b = run(shuffled);
      // Two partial states merged (e.g. two tiles or threads).
      const std::vector<Seg> first(segs.begin(), segs.begin() + 3), second(segs.begin() + 3, segs.end());
      hov::RayBlendState merged = run(second);
      hov::MergeBlendStates(merged, run(first), bs);
      const std::string where = "trial " + std::to_string(trial) + " mode " + std::to_string(static_cast<int>(mode));
      EXPECT_EQ(a.Value, b.Value) << where;
      EXPECT_EQ(a.T, b.T) << where;
      EXPECT_EQ(a.Value, merged.Value) << where;
      EXPECT_EQ(a.T, merged.T) << where;
      sumErr.Add(std::max({ std::fabs(a.WeightedIntegral - b.WeightedIntegral),
                   std::fabs(a.InRangeLength - merged.InRangeLength),
                   std::fabs(a.ScalarIntegral - merged.ScalarIntegral) }),
        where);
      // Splitting a linear segment in two gives the same sums.
      const Seg& g = segs[0];
      const double x = hovtest::Uniform(rng, 0.05, 0.95);
      const double sx = g.SF + (g.SB - g.SF) * x;
      hov::RayBlendState whole, halves;
      hov::AccumulateLinearSegment(whole, bs, table, g.T, g.L, g.SF, g.SB);
      hov::AccumulateLinearSegment(halves, bs, table, g.T, g.L * x, g.SF, sx);
      hov::AccumulateLinearSegment(halves, bs, table, g.T + g.L * x, g.L * (1 - x), sx, g.SB);
      splitErr.Add(std::max({ std::fabs(whole.WeightedIntegral - halves.WeightedIntegral),
                     std::fabs(whole.InRangeLength - halves.InRangeLength),
                     std::fabs(whole.ScalarIntegral - halves.ScalarIntegral) }),
        where);
    }
  }
  hovtest::ReportMeasured("BlendModes.ReorderedSums", sumErr);
  hovtest::ReportMeasured("BlendModes.SplitSums", splitErr);
  EXPECT_LE(sumErr.Value, Tolerances.BlendCompositionAbs) << sumErr.Where;
  EXPECT_LE(splitErr.Value, Tolerances.BlendCompositionAbs) << splitErr.Where;
}

TEST(BlendModes, ContinuityAcrossBranches)
{
  std::mt19937_64 rng(1905);
  const hov::TransferFunctionSpec spec = RandomSpec(rng, 5, 5);
  const hov::TransferFunction table = RawTable(spec);
  Worst quadToLinear, flatToSloped, limitCrossing;
  for (int trial = 0; trial < 200; ++trial)
  {
    const double sF = hovtest::Uniform(rng, 0, 1), sB = hovtest::Uniform(rng, 0, 1), L = 0.7;
    const std::string where = "trial " + std::to_string(trial);
    // (1) degree 2 with a vanishing quadratic term -> the linear path.
    for (hov::BlendMode mode : { hov::BlendMode::MaximumIntensity, hov::BlendMode::AverageIntensity })
    {
      hov::BlendSettings bs;
      bs.Mode = mode;
      hov::RayBlendState lin, quad;
      hov::AccumulateLinearSegment(lin, bs, table, 0.0, L, sF, sB);
      const double eps2 = 1e-13;
      hov::Polynomial p = hov::Polynomial::FromCoefficients({ sF, (sB - sF) / L - eps2 * L, eps2 });
      hov::AccumulatePolynomialSegment(quad, bs, table, 0.0, L, p);
      quadToLinear.Add(std::max({ std::fabs(lin.Value - quad.Value),
                         std::fabs(lin.WeightedIntegral - quad.WeightedIntegral),
                         std::fabs(lin.InRangeLength - quad.InRangeLength) }),
        where);
    }
    // (2) sB -> sF: the constant branch (ds == 0) vs a tiny slope.
    hov::BlendSettings avg;
    avg.Mode = hov::BlendMode::AverageIntensity;
    hov::RayBlendState flat, sloped;
    hov::AccumulateLinearSegment(flat, avg, table, 0.0, L, sF, sF);
    hov::AccumulateLinearSegment(sloped, avg, table, 0.0, L, sF, sF + 1e-12);
    flatToSloped.Add(std::fabs(flat.WeightedIntegral - sloped.WeightedIntegral), where);
    // (3) the average range's limit moving across the segment's end value.
    hov::BlendSettings below = avg, above = avg;
    below.AverageRange[0] = sF - 1e-12;
    above.AverageRange[0] = sF + 1e-12;
    hov::RayBlendState b, a;
    hov::AccumulateLinearSegment(b, below, table, 0.0, L, sF, sB);
    hov::AccumulateLinearSegment(a, above, table, 0.0, L, sF, sB);
    // Lipschitz in the limit with constant L / |sB - sF|: compare on that scale.
    limitCrossing.Add(std::max(std::fabs(b.WeightedIntegral - a.WeightedIntegral),
                        std::fabs(b.InRangeLength - a.InRangeLength)) * std::fabs(sB - sF) / L,
      where);
  }
  hovtest::ReportMeasured("BlendModes.ContinuityQuadraticToLinear", quadToLinear);
  hovtest::ReportMeasured("BlendModes.ContinuityFlatToSloped", flatToSloped);
  hovtest::ReportMeasured("BlendModes.ContinuityRangeLimit", limitCrossing);
  EXPECT_LE(quadToLinear.Value, Tolerances.BlendContinuityAbs) << quadToLinear.Where;
  EXPECT_LE(flatToSloped.Value, Tolerances.BlendContinuityAbs) << flatToSloped.Where;
  EXPECT_LE(limitCrossing.Value, Tolerances.BlendContinuityAbs) << limitCrossing.Where;
}

TEST(BlendModes, ResolveFollowsVTKSemantics)
{
  // Colour ramp black -> (2, 1, 0.5) (clamped by the GPU: channels > 1 -> 1),
  // opacity 0.2 -> 0.8 over [0, 1]; GPU semantics and a unit distance that the
  // blend modes must ignore (VTK corrects the opacity table only for COMPOSITE).
  hov::TransferFunctionSpec spec;
  spec.Color = { { 0.0, 0.0, 0.0, 0.0 }, { 1.0, 2.0, 1.0, 0.5 } };
  spec.Opacity = { { 0.0, 0.2 }, { 1.0, 0.8 } };
  spec.UnitDistance = 0.01;
  const hov::TransferFunction table = RawTable(spec);
  hov::BlendSettings bs;
  hov::RayBlendState st;
  hov::AccumulateLinearSegment(st, bs, table, 2.0, 1.0, 0.25, 0.75);
  hov::RGBA px = hov::ResolveBlend(st, bs, table);
  // s = 0.75: colour (1.5 -> 1, 0.75, 0.375), a = 0.65; premultiplied.
  EXPECT_NEAR(px.A, 0.65, Tolerances.FewUlpAbs);
  EXPECT_NEAR(px.R, 1.0 * 0.65, Tolerances.FewUlpAbs);
  EXPECT_NEAR(px.G, 0.75 * 0.65, Tolerances.FewUlpAbs);
  EXPECT_NEAR(px.B, 0.375 * 0.65, Tolerances.FewUlpAbs);
  EXPECT_EQ(st.T, 3.0);
  bs.Mode = hov::BlendMode::MinimumIntensity;
  hov::RayBlendState mn;
  hov::AccumulateLinearSegment(mn, bs, table, 2.0, 1.0, 0.25, 0.75);
  px = hov::ResolveBlend(mn, bs, table);
  EXPECT_NEAR(px.A, 0.35, Tolerances.FewUlpAbs);
  EXPECT_NEAR(px.R, 0.5 * 0.35, Tolerances.FewUlpAbs);
  EXPECT_EQ(mn.T, 2.0);
  // Average: a(s) sn(s) with sn = s on [0, 1]: int_0.25^0.75 (0.2 + 0.6 s) s ds / 0.5.
  bs.Mode = hov::BlendMode::AverageIntensity;
  hov::RayBlendState av;
  hov::AccumulateLinearSegment(av, bs, table, 2.0, 1.0, 0.25, 0.75);
  px = hov::ResolveBlend(av, bs, table);
  const double expected = ((0.1 * 0.5625 + 0.2 * 0.421875) - (0.1 * 0.0625 + 0.2 * 0.015625)) / 0.5;
  EXPECT_NEAR(px.R, expected, Tolerances.FewUlpAbs);
  EXPECT_EQ(px.G, px.R);
  EXPECT_EQ(px.A, 1.0); // opaque grey, as the GPU mapper
  // No sample in range: transparent (the GPU discards the fragment).
  bs.AverageRange[0] = 2.0;
  bs.AverageRange[1] = 3.0;
  hov::RayBlendState none;
  hov::AccumulateLinearSegment(none, bs, table, 2.0, 1.0, 0.25, 0.75);
  px = hov::ResolveBlend(none, bs, table);
  EXPECT_EQ(px.A, 0.0);
  EXPECT_EQ(px.R, 0.0);
  // Nothing seen: transparent in every mode.
  EXPECT_EQ(hov::ResolveBlend(hov::RayBlendState(), bs, table).A, 0.0);
}

TEST(BlendModes, DegenerateInputHasNoNaN)
{
  hov::TransferFunctionSpec spec;
  spec.Color = { { 0.0, 1.0, 1.0, 1.0 } };
  spec.Opacity = { { 0.0, 0.5 } };
  const hov::TransferFunction table = RawTable(spec);
  hov::TransferFunction empty; // never built: no nodes
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (hov::BlendMode mode : { hov::BlendMode::MaximumIntensity, hov::BlendMode::MinimumIntensity,
         hov::BlendMode::AverageIntensity })
  {
    hov::BlendSettings bs;
    bs.Mode = mode;
    bs.ScalarRange[0] = bs.ScalarRange[1] = 3.0; // empty range: sn = 0
    bs.AverageRange[0] = nan;
    for (const hov::TransferFunction* tf : std::vector<const hov::TransferFunction*>{ &table, &empty })
    {
      hov::RayBlendState st;
      hov::AccumulateLinearSegment(st, bs, *tf, 0.0, 0.0, 1.0, 2.0);   // zero length
      hov::AccumulateLinearSegment(st, bs, *tf, 0.0, -1.0, 1.0, 2.0);  // negative length
      hov::AccumulateLinearSegment(st, bs, *tf, 0.0, 1.0, nan, 2.0);   // NaN scalar
      hov::AccumulateLinearSegment(st, bs, *tf, 0.0, inf, 1.0, 2.0);   // infinite length
      hov::Polynomial bad = hov::Polynomial::FromCoefficients({ 1.0, nan, 2.0 });
      hov::AccumulatePolynomialSegment(st, bs, *tf, 0.0, 1.0, bad);
      hov::AccumulatePolynomialSegment(st, bs, *tf, 0.0, 1.0, hov::Polynomial::FromCoefficients({ 1.0, 2.0, 3.0 }), nan);
      EXPECT_EQ(st.SkippedSegments, 6);
      EXPECT_FALSE(st.Found);
      hov::RGBA px = hov::ResolveBlend(st, bs, *tf);
      EXPECT_EQ(px.A, 0.0);
      // Valid but extreme input: values near the double range, a huge polynomial.
      hov::AccumulateLinearSegment(st, bs, *tf, 0.0, 1e-300, 1e300, -1e300);
      hov::AccumulateLinearSegment(st, bs, *tf, 1.0, 1e300, 0.5, 0.5);
      hov::AccumulatePolynomialSegment(st, bs, *tf, 2.0, 1e-3, hov::Polynomial::FromCoefficients({ 1e200, -1e250, 1e300 }));
      px = hov::ResolveBlend(st, bs, *tf);
      EXPECT_TRUE(hovtest::AllFinite(px));
      EXPECT_TRUE(std::isfinite(st.Value) && std::isfinite(st.WeightedIntegral) && std::isfinite(st.InRangeLength));
      EXPECT_TRUE(std::isfinite(st.ErrorBound));
    }
  }
}
