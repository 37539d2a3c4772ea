// Tests of hovShadedSegment: the adaptive spectral quadrature of a shaded,
// gradient-opacity-modulated segment whose gradient varies along the ray
// (quadratic fields: s(t) quadratic, grad s(t) linear in t, as in a quadratic
// tetrahedron) against an independent long double reference (raw-node
// transfer and gradient-opacity functions, Blinn-Phong transcribed in long
// double per point, breakpoints located by bisection, Boost Gauss-Kronrod,
// hovFeatureTestReference.h): the error is below the requested tolerance AND
// below the reported ErrorEstimate (the estimate is an upper bound in
// practice, measured), for tolerances 1e-6, 1e-9, 1e-12; the closed-form path
// for constant gradients; degenerate input.

#include "hovShadedSegment.h"

#include "hovPolynomialSegment.h" // the unshaded route past many crossings
#include "hovGradientOpacity.h"
#include "hovTransferFunction.h"
#include "hovVolumeShading.h"

#include "hovFeatureTestReference.h"
#include "hovShadedSegmentTestCase.h"
#include "hovKernelTestTolerances.h"
#include "hovKernelTestUtilities.h"

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

using hovtest::Case;
using hovtest::RandomCase;
using hovtest::Reference;
using hovtest::Directional;

TEST(ShadedSegment, QuadraticFieldsAgainstLongDoubleReference)
{
  std::mt19937_64 rng(1921);
  Worst err[3], ratio, refSelf;
  int panels[3] = { 0, 0, 0 };
  const double tolerances[3] = { 1e-6, 1e-9, 1e-12 };
  for (int trial = 0; trial < 40; ++trial)
  {
    const Case c = RandomCase(rng, trial);
    const hovtest::CaseInputs in(c);
    const hov::TransferFunction& tf = in.TF;
    const hov::GradientOpacityFunction& go = in.GO;
    const hov::VolumeShadingSettings& vs = in.Shading;
    const hov::Polynomial& s = in.S;
    const hov::Polynomial* g = in.G;
    const hov::SegmentRay& ray = in.Ray;
    for (hov::EmissionModel em : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
    {
      const bool wvg = em == hov::EmissionModel::WilhelmsVanGelder;
      double selfError = 0.0;
      const hovtest::RefRGBA ref = Reference(c, em, &selfError);
      refSelf.Add(selfError, "trial " + std::to_string(trial));
      for (int k = 0; k < 3; ++k)
      {
        hov::ShadedSegmentSettings settings;
        settings.Emission = em;
        settings.Tolerance = tolerances[k];
        const hov::ShadedSegmentResult r =
          hov::IntegrateShadedPolynomial(tf, s, g, c.Length, vs, c.GO.Nodes.empty() ? nullptr : &go, ray, settings);
        EXPECT_FALSE(r.ExactPath);
        EXPECT_TRUE(r.Converged) << "trial " << trial << " tol " << tolerances[k];
        const double e = hovtest::MaxAbsDiff(r.Color, ref, 1.0);
        const std::string where = "trial " + std::to_string(trial) + (wvg ? " WVG" : " WM") +
          " tol " + Str(tolerances[k]) + " estimate " + Str(r.ErrorEstimate);
        err[k].Add(e, where);
        EXPECT_LE(e, std::max(tolerances[k], 1e-13)) << where;
        // The estimate bounds the error (up to the reference's own rounding).
        ratio.Add(e / (r.ErrorEstimate + 1e-14), where);
        EXPECT_LE(r.ErrorEstimate, tolerances[k] * 1.0000001) << where;
        panels[k] += r.Panels;
      }
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    hovtest::ReportMeasured("ShadedSegment.QuadraticVsReference tol " + Str(tolerances[k]), err[k]);
    std::cout << "[measured] ShadedSegment panels at tol " << tolerances[k] << ": " << panels[k] << "\n";
    EXPECT_LE(err[k].Value, std::max(tolerances[k], 1e-13)) << err[k].Where;
  }
  hovtest::ReportMeasured("ShadedSegment.ReferenceSelfCheck (8 vs 16 panels)", refSelf);
  EXPECT_LE(refSelf.Value, 1e-15) << refSelf.Where;
  hovtest::ReportMeasured("ShadedSegment.ErrorOverEstimate", ratio);
  EXPECT_LE(ratio.Value, 1.0) << ratio.Where;
  // Tighter tolerance: more panels.
  EXPECT_LE(panels[0], panels[1]);
  EXPECT_LE(panels[1], panels[2]);
}

TEST(ShadedSegment, ConstantGradientTakesTheClosedForm)
{
  std::mt19937_64 rng(1922);
  for (int trial = 0; trial < 50; ++trial)
  {
    Case c = RandomCase(rng, trial);
    for (auto& row : c.F.Q)
    {
      for (double& q : row)
      {
        q = 0.0;
      }
    }
    hov::TransferFunction tf;
    tf.Build(c.Spec);
    hov::GradientOpacityFunction go;
    go.Build(c.GO);
    hov::VolumeShadingSettings vs;
    vs.Shade = true;
    vs.Material = c.Material;
    vs.Lights = c.Lights.data();
    vs.LightCount = static_cast<int>(c.Lights.size());
    hov::Polynomial s, g[3];
    c.F.Polynomials(s, g);
    hov::SegmentRay ray;
    for (int i = 0; i < 3; ++i)
    {
      ray.Direction[i] = c.F.D[i];
    }
    hov::ShadedSegmentSettings settings;
    const hov::ShadedSegmentResult r = hov::IntegrateShadedPolynomial(tf, s, g, c.Length, vs, &go, ray, settings);
    ASSERT_TRUE(r.ExactPath);
    const double gc[3] = { g[0].C[0], g[1].C[0], g[2].C[0] };
    const double v[3] = { -c.F.D[0], -c.F.D[1], -c.F.D[2] };
    const hov::RGBA e = hov::IntegrateLinearScalarShaded(tf, s.C[0], s.C[0] + s.C[1] * c.Length, c.Length,
      hov::ComputeShadingTransform(vs, gc, ray.Origin, v), go.EvaluateGradient(gc), hov::IntegrationSettings());
    EXPECT_EQ(r.Color.R, e.R);
    EXPECT_EQ(r.Color.A, e.A);
    // And the closed form agrees with the independent reference.
    const hovtest::RefRGBA ref = Reference(c, hov::EmissionModel::WilliamsMax);
    EXPECT_LE(hovtest::MaxAbsDiff(r.Color, ref, 1.0), Tolerances.ShadedReferenceAbs) << trial;
  }
}

TEST(ShadedSegment, DegenerateInput)
{
  hov::TransferFunctionSpec spec;
  spec.Color = { { 0.0, 1.0, 0.5, 0.2 } };
  spec.Opacity = { { 0.0, 0.5 } };
  hov::TransferFunction tf;
  tf.Build(spec);
  hov::VolumeShadingSettings vs;
  const hov::ShadingLight light = Directional(0, 0, -1);
  vs.Shade = true;
  vs.Lights = &light;
  vs.LightCount = 1;
  hov::Polynomial s = hov::Polynomial::FromCoefficients({ 0.5, 0.1, 0.3 });
  hov::Polynomial g[3] = { hov::Polynomial::FromCoefficients({ 0.1, 1.0 }),
    hov::Polynomial::FromCoefficients({ 0.0 }), hov::Polynomial::FromCoefficients({ 1.0 }) };
  const hov::SegmentRay ray;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double L : { 0.0, -1.0, nan, std::numeric_limits<double>::infinity() })
  {
    const hov::ShadedSegmentResult r = hov::IntegrateShadedPolynomial(tf, s, g, L, vs, nullptr, ray, {});
    EXPECT_EQ(r.Color.A, 0.0) << L;
    EXPECT_TRUE(hovtest::AllFinite(r.Color));
  }
  hov::Polynomial bad = s;
  bad.C[1] = nan;
  const hov::ShadedSegmentResult r = hov::IntegrateShadedPolynomial(tf, bad, g, 1.0, vs, nullptr, ray, {});
  EXPECT_EQ(r.Color.A, 0.0);
  EXPECT_FALSE(r.Converged);
  // The gradient vanishing at one point of the segment (n undefined there): finite, converged.
  hov::Polynomial g0[3] = { hov::Polynomial::FromCoefficients({ -0.5, 1.0 }),
    hov::Polynomial::FromCoefficients({ 0.0 }), hov::Polynomial::FromCoefficients({ 0.0 }) };
  const hov::ShadedSegmentResult z = hov::IntegrateShadedPolynomial(tf, s, g0, 1.0, vs, nullptr, ray, {});
  EXPECT_TRUE(hovtest::AllFinite(z.Color));
  EXPECT_GT(z.Color.A, 0.0);
}

// A table refined to a tight GPU tolerance has thousands of nodes and a steep
// field crosses them all: each crossing used to cost a piece with its own
// panel (17 samples: for a general cell each one a Newton inversion). The
// refinement's nodes are smooth (TransferFunction::IsSmoothNode: tau convex,
// colour linear), so the integral steps over evenly spaced ones of them and
// keeps every other breakpoint; it stays within its error estimate of the
// integral with every breakpoint kept, also with an opaque interval entered
// by a jump, a narrow opaque band with the same opacity on both sides, and a
// narrow spike without jumps (the bands a merged piece could step over if
// their nodes were not kept). Unshaded polynomial segments take the same
// route past MaxPanels / 2 crossings (hovPolynomialSegment.h).
namespace
{
/// ShadedBreakpoints with a piece limit leaves out only mergeable crossings,
/// keeps every other breakpoint and flag, and spreads the kept ones evenly.
void CheckPreThinning(const hov::TransferFunction& tf, const hov::Polynomial& s,
  const hov::Polynomial g[3], double L, const std::string& name)
{
  std::vector<double> all, kept;
  std::vector<unsigned char> allFlags, keptFlags;
  hov::ShadedBreakpoints(tf, s, g, nullptr, L, all, &allFlags);
  const long long mergeable = std::count(allFlags.begin(), allFlags.end(), 1);
  for (int maxPieces : { 128, 2048 })
  {
    const std::string at = name + " pre-thinned to " + std::to_string(maxPieces);
    int skipped = -1;
    hov::ShadedBreakpoints(tf, s, g, nullptr, L, kept, &keptFlags, maxPieces, &skipped);
    ASSERT_EQ(kept.size(), keptFlags.size()) << at;
    EXPECT_LE(static_cast<int>(kept.size()) + 1, maxPieces) << at;
    EXPECT_EQ(static_cast<long long>(all.size()) - skipped, static_cast<long long>(kept.size())) << at;
    const long long keptMergeable = std::count(keptFlags.begin(), keptFlags.end(), 1);
    // Walk both sorted lists: the kept ones are a subset with the same flags,
    // no non-mergeable one is missing, and no run of skipped ones is longer
    // than the even spacing allows.
    const long long longestRun = keptMergeable > 0 ? mergeable / keptMergeable + 2 : mergeable;
    size_t k = 0;
    long long run = 0, worstRun = 0;
    for (size_t i = 0; i < all.size(); ++i)
    {
      if (k < kept.size() && kept[k] == all[i])
      {
        EXPECT_EQ(keptFlags[k], allFlags[i]) << at << " at t = " << all[i];
        ++k;
        run = 0;
        continue;
      }
      EXPECT_EQ(allFlags[i], 1) << at << ": a breakpoint that is not mergeable left out, t = " << all[i];
      worstRun = std::max(worstRun, ++run);
    }
    EXPECT_EQ(k, kept.size()) << at << ": kept breakpoints not in the full list";
    EXPECT_LE(worstRun, longestRun) << at;
  }
}

/// Three colour nodes and @p opacity, GPU-compatible, refined to 1e-8 (thousands of nodes).
hov::TransferFunctionSpec RefinedSpec(const std::vector<hov::OpacityNode>& opacity)
{
  hov::TransferFunctionSpec spec;
  spec.Color = { { 0.0, 0.9, 0.2, 0.1 }, { 0.5, 0.2, 0.8, 0.3 }, { 1.0, 0.1, 0.3, 0.9 } };
  spec.Opacity = opacity;
  spec.Semantics = hov::OpacitySemantics::GPUCompatible;
  spec.UnitDistance = 0.5;
  spec.GPUTolerance = 1e-8;
  spec.RefinementBudget = 16384;
  return spec;
}

void CheckManyBreakpoints(const std::vector<hov::OpacityNode>& opacity, const std::string& name)
{
  const hov::TransferFunctionSpec spec = RefinedSpec(opacity);
  hov::TransferFunction tf;
  tf.Build(spec);
  ASSERT_GT(tf.GetNumberOfNodes(), 2000);
  // The refinement's nodes are smooth; a jump (two user nodes at one X) and
  // a peak of the opacity (tau concave there) never are.
  const std::vector<double>& x = tf.GetNodes();
  int smoothNodes = 0;
  for (int k = 0; k < tf.GetNumberOfNodes(); ++k)
  {
    smoothNodes += tf.IsSmoothNode(k);
  }
  EXPECT_GT(smoothNodes, tf.GetNumberOfNodes() * 9 / 10) << name;
  int sharp = 0;
  for (size_t j = 1; j + 1 < opacity.size(); ++j)
  {
    const bool jump = opacity[j].X == opacity[j - 1].X || opacity[j].X == opacity[j + 1].X;
    const bool peak =
      opacity[j].Opacity > opacity[j - 1].Opacity && opacity[j].Opacity > opacity[j + 1].Opacity;
    for (int k = 0; (jump || peak) && k < tf.GetNumberOfNodes(); ++k)
    {
      if (x[k] == opacity[j].X)
      {
        EXPECT_FALSE(tf.IsSmoothNode(k)) << name << ": node " << k << " at " << x[k];
        ++sharp;
      }
    }
  }
  EXPECT_GT(sharp, 0) << name; // every case has a peak or a jump
  hov::VolumeShadingSettings vs;
  const hov::ShadingLight light = Directional(0.3, 0.2, -1);
  vs.Shade = true;
  vs.Material.Ambient = 0.2;
  vs.Material.Diffuse = 0.7;
  vs.Material.Specular = 0.3;
  vs.Material.SpecularPower = 10;
  vs.Lights = &light;
  vs.LightCount = 1;
  // s from 0 to 1 and back down to 0.3 over the segment: it crosses most nodes twice.
  const double L = 0.8;
  const hov::Polynomial s = hov::Polynomial::FromCoefficients({ 0.0, 4.25, -4.3 });
  const hov::Polynomial g[3] = { hov::Polynomial::FromCoefficients({ 0.4, -1.0 }),
    hov::Polynomial::FromCoefficients({ 0.1 }), hov::Polynomial::FromCoefficients({ 1.0, 0.5 }) };
  const hov::SegmentRay ray;
  std::vector<double> breaks;
  const int crossings = hov::ShadedBreakpoints(tf, s, g, nullptr, L, breaks);
  ASSERT_GT(crossings, 3000);
  CheckPreThinning(tf, s, g, L, name);
  for (hov::EmissionModel em : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
  {
    const std::string where = name + (em == hov::EmissionModel::WilliamsMax ? " WM" : " WVG");
    hov::ShadedSegmentSettings every; // every breakpoint its own piece
    every.Emission = em;
    every.Tolerance = 1e-10;
    every.MaxPanels = 1 << 17; // 65,536 pieces: none merged
    const hov::ShadedSegmentResult ref = hov::IntegrateShadedPolynomial(tf, s, g, L, vs, nullptr, ray, every);
    EXPECT_EQ(ref.SkippedBreakpoints, 0) << where;
    if (name == "smooth")
    {
      EXPECT_GE(ref.Panels, crossings) << where; // one piece per crossing at least
    }
    for (int maxPanels : { 256, 4096 })
    {
      hov::ShadedSegmentSettings settings;
      settings.Emission = em;
      settings.Tolerance = 1e-6;
      settings.MaxPanels = maxPanels;
      const hov::ShadedSegmentResult r = hov::IntegrateShadedPolynomial(tf, s, g, L, vs, nullptr, ray, settings);
      const std::string at = where + " MaxPanels " + std::to_string(maxPanels);
      // Pieces: the kept breakpoints + 1 <= MaxPanels / 2 (the user's
      // nodes here are few; a ray that turns opaque stops counting there).
      // Accepted panels: one per piece at least, bisections while the budget
      // lasts (up to MaxDepth waiting on the stack), so under MaxPanels +
      // MaxPanels / 2 + MaxDepth (41 by default); 17 samples per panel tried
      // (at most twice the accepted ones) and one per piece.
      if (name == "smooth")
      {
        EXPECT_EQ(r.SkippedBreakpoints, crossings - (maxPanels / 2 - 1)) << at;
      }
      EXPECT_GT(r.SkippedBreakpoints, 0) << at;
      EXPECT_LE(r.SkippedBreakpoints, crossings - (maxPanels / 2 - 1)) << at;
      EXPECT_LE(r.Panels, maxPanels + maxPanels / 2 + 41) << at;
      EXPECT_LE(r.Samples, 34 * r.Panels + maxPanels / 2) << at;
      EXPECT_LE(r.Samples * 4, ref.Samples) << at;
      const double e = hovtest::MaxAbsDiff(r.Color, ref.Color);
      std::cout << "[measured] ShadedSegment many breakpoints " << at << ": " << crossings
                << " crossings, " << r.Panels << " panels, " << r.Samples << " samples (every breakpoint: "
                << ref.Samples << "), error " << e << ", estimate " << r.ErrorEstimate
                << (r.Converged ? "" : ", not converged") << "\n";
      EXPECT_TRUE(hovtest::AllFinite(r.Color)) << at;
      EXPECT_LE(e, r.ErrorEstimate + ref.ErrorEstimate + 1e-14) << at;
      EXPECT_LE(e, 1e-4) << at;
    }
  }
  // Unshaded, IntegratePolynomialScalar: past MaxPanels / 2 crossings, nearly
  // all smooth, the sampled route (32 pieces, bisected as needed) is tried
  // within a budget of crossings / 64 panel evaluations; if it does not
  // converge there the exact walk (one exact piece per crossing) runs after all.
  for (hov::EmissionModel em : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
  {
    hov::PolynomialSegmentSettings exact;
    exact.Emission = em;
    exact.MaxPanels = 1 << 20; // room for every crossing: the exact walk
    const hov::PolynomialSegmentResult ref = hov::IntegratePolynomialScalar(tf, s, L, exact);
    EXPECT_FALSE(ref.Sampled) << name;
    if (name == "smooth")
    {
      EXPECT_GE(ref.Pieces, crossings) << name;
    }
    for (double tolerance : { 1e-9, 1e-6 })
    {
      const std::string at = name + (em == hov::EmissionModel::WilliamsMax ? " WM" : " WVG") +
        " unshaded tolerance " + std::to_string(tolerance);
      hov::PolynomialSegmentSettings settings; // MaxPanels 4096
      settings.Emission = em;
      settings.Tolerance = tolerance;
      const hov::PolynomialSegmentResult r = hov::IntegratePolynomialScalar(tf, s, L, settings);
      const double e = hovtest::MaxAbsDiff(r.Color, ref.Color);
      std::cout << "[measured] ShadedSegment many breakpoints " << at << ": exact walk " << ref.Pieces
                << " pieces; " << (r.Sampled ? "sampled, " : "exact walk, ") << r.Panels
                << " panels, error " << e << ", estimate " << r.ErrorEstimate << "\n";
      EXPECT_TRUE(hovtest::AllFinite(r.Color)) << at;
      if (r.Sampled)
      {
        EXPECT_TRUE(r.Converged) << at; // else the exact walk
        // Budget: (all the crossings + 1) / 64 panel evaluations, at most MaxPanels.
        EXPECT_LE(r.Panels, std::min((crossings + 1) / 64 + 1, 4096)) << at;
        EXPECT_LE(e, r.ErrorEstimate + ref.ErrorEstimate + 1e-14) << at;
        EXPECT_LE(e, tolerance) << at;
      }
      else
      {
        EXPECT_EQ(e, 0.0) << at;
      }
      // What the route is for: the refinement of a smooth function at a
      // moderate tolerance, and whatever lies in front of an opaque medium.
      if (name == "opaque" || (tolerance == 1e-6 && name == "smooth"))
      {
        EXPECT_TRUE(r.Sampled) << at;
      }
    }
  }
}
}

TEST(ShadedSegment, ManyBreakpointsHaveABoundedCost)
{
  CheckManyBreakpoints({ { 0.0, 0.0 }, { 0.45, 0.6 }, { 0.7, 0.95 }, { 1.0, 0.1 } }, "smooth");
  CheckManyBreakpoints({ { 0.0, 0.0 }, { 0.45, 0.3 }, { 0.62, 0.3 }, { 0.62, 1.0 }, { 0.66, 1.0 },
                         { 0.66, 0.2 }, { 1.0, 0.1 } },
    "opaque");
  // 2e-4 wide, far narrower than a merged piece's sample spacing.
  CheckManyBreakpoints({ { 0.0, 0.0 }, { 0.45, 0.5 }, { 0.62, 0.3 }, { 0.62, 1.0 }, { 0.6202, 1.0 },
                         { 0.6202, 0.3 }, { 1.0, 0.1 } },
    "narrow opaque band");
  CheckManyBreakpoints({ { 0.0, 0.0 }, { 0.45, 0.5 }, { 0.6199, 0.3 }, { 0.62, 0.999 },
                         { 0.6201, 0.3 }, { 1.0, 0.1 } },
    "narrow spike");
  // s peaks at 1.0501453, 5.3e-6 past a node where the opacity starts a
  // steep rise (smooth: tau convex there), so tau(s(t)) has a bump 2e-3 long
  // around the peak. The extremum of s is always a breakpoint (s monotone in
  // every piece: tau peaks at a piece's end, which is sampled). Here the
  // dense crossings around the peak also keep breakpoints near it: with the
  // extremum mergeable this case still passed (error 1.3e-9), so it checks
  // the accuracy, not that rule.
  CheckManyBreakpoints({ { 0.0, 0.0 }, { 0.45, 0.6 }, { 0.7, 0.95 }, { 1.0, 0.0 }, { 1.05014, 0.0 },
                         { 1.0502, 0.99 } },
    "peak of s past a convex node");
}

// The unshaded sampled route is taken only where it applies, and a try that
// cannot converge stops within its evaluations: a tolerance that is not a
// positive number, or an end of a monotone run within rounding of a table
// node (the exact walk snaps it, the route would not), keep the exact walk,
// bit for bit; a control segment a little away from the node is sampled.
TEST(ShadedSegment, SampledRouteOnlyWhereItApplies)
{
  hov::TransferFunction tf;
  tf.Build(RefinedSpec({ { 0.0, 0.0 }, { 0.45, 0.6 }, { 0.7, 0.95 }, { 1.0, 0.1 } }));
  const std::vector<double>& x = tf.GetNodes();
  const double L = 0.8;
  // s rises from 0.05 to its peak at t = L / 2 (about 0.86) and falls back.
  const double peak = 0.86, low = 0.05;
  auto field = [&](double sPeak) {
    const double rise = sPeak - low;
    return hov::Polynomial::FromCoefficients({ low, 4.0 * rise / L, -4.0 * rise / (L * L) });
  };
  hov::PolynomialSegmentSettings settings;
  settings.Tolerance = 1e-6;
  hov::PolynomialSegmentSettings exact = settings;
  exact.MaxPanels = 1 << 20;
  // The first node at or above the peak; the control peaks half-way to the
  // next one. Both runs cross the nodes in [0.05, peak]: thousands.
  const int k = static_cast<int>(std::lower_bound(x.begin(), x.end(), peak) - x.begin());
  ASSERT_TRUE(k > 0 && k + 1 < tf.GetNumberOfNodes());
  const long long crossed = 2 * (k - (std::lower_bound(x.begin(), x.end(), low) - x.begin()));
  ASSERT_GE(crossed, 4096) << "the refined table has too few nodes for the route";
  const double away = 0.5 * (x[k] + x[k + 1]);
  const hov::PolynomialSegmentResult control = hov::IntegratePolynomialScalar(tf, field(away), L, settings);
  EXPECT_TRUE(control.Sampled) << crossed << " crossings";
  // On the node (within NodeSnap: the exact walk snaps it) and 3e-15 above
  // it (outside NodeSnap, about 1.5e-15 here, inside Horner's bound, about
  // 6.6e-15 for this field): the exact walk, bit for bit.
  for (double onNode : { x[k], x[k] + 3e-15 })
  {
    const hov::PolynomialSegmentResult r = hov::IntegratePolynomialScalar(tf, field(onNode), L, settings);
    const hov::PolynomialSegmentResult ref = hov::IntegratePolynomialScalar(tf, field(onNode), L, exact);
    EXPECT_FALSE(r.Sampled) << "peak at " << onNode - x[k] << " from a node";
    EXPECT_EQ(hovtest::MaxAbsDiff(r.Color, ref.Color), 0.0) << "peak at " << onNode - x[k] << " from a node";
  }
  for (double tolerance : { 0.0, -1.0, std::numeric_limits<double>::quiet_NaN() })
  {
    hov::PolynomialSegmentSettings bad = settings;
    bad.Tolerance = tolerance;
    const hov::PolynomialSegmentResult r = hov::IntegratePolynomialScalar(tf, field(away), L, bad);
    EXPECT_FALSE(r.Sampled) << "tolerance " << tolerance;
    EXPECT_TRUE(hovtest::AllFinite(r.Color)) << "tolerance " << tolerance;
  }
  // StopWhenUnconverged: out of evaluations long before the end.
  const hov::Polynomial noGradient[3] = {};
  hov::ShadedSegmentSettings tight;
  tight.Tolerance = 1e-12;
  tight.MaxPanels = 8;
  tight.StopWhenUnconverged = true;
  const hov::ShadedSegmentResult stopped = hov::IntegrateShadedPolynomial(
    tf, field(away), noGradient, L, hov::VolumeShadingSettings(), nullptr, hov::SegmentRay(), tight);
  EXPECT_FALSE(stopped.Converged);
  EXPECT_LE(stopped.Panels, 8);
  // At most 8 evaluations of 17 samples, and one midpoint sample per piece
  // begun (the first piece alone bisects 40 times if evaluations are not counted).
  EXPECT_LE(stopped.Samples, 8 * 17 + 9);
  tight.StopWhenUnconverged = false; // the same budget, every piece still integrated
  const hov::ShadedSegmentResult finished = hov::IntegrateShadedPolynomial(
    tf, field(away), noGradient, L, hov::VolumeShadingSettings(), nullptr, hov::SegmentRay(), tight);
  EXPECT_GT(finished.Panels, stopped.Panels);
}
