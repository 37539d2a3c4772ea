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
#include "hovBlendTestTables.h"

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

using hovtest::RandomSpec;
using hovtest::RawTable;

namespace
{

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
