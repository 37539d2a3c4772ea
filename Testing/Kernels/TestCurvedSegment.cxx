// Segment categorization and integration in (curved) Lagrange cells
// (hovCurvedSegment.h):
//  - E / PS / S and occlusion-only on hand-made ranges;
//  - ElVis's verification field f = x^2 + y^2 + z^2 on an axis-aligned
//    hexahedron (orders 2 and 3; affine path) against the independent
//    reference of hovPolynomialTestSupport.h (breakpoints by bisection in
//    long double, adaptive Gauss-Kronrod), every ray through the cell;
//  - a CURVED hexahedron whose geometry map has a polynomial inverse
//    (x = r + a s^2, y = s, z = t, so pc(t) and the field along any ray are
//    polynomials in t): the curved path (Chebyshev pieces, polished
//    breakpoints) against the same reference;
//  - breakpoints located on bent cells against bisection roots of the exact
//    field along the ray;
//  - empty segments are exactly transparent;
//  - table nodes outside a segment's range change neither its colour nor
//    (beyond noise) its cost.
#include "hovCurvedSegment.h"

#include "hovCurvedRayCell.h"
#include "hovKernelTestUtilities.h"
#include "hovLagrangeTestSupport.h"
#include "hovPolynomialTestSupport.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>

namespace
{
using hov::SegmentCategory;

/// A table with breakpoints at 0.3, 0.7, 1.2 (ElVis-like: a zero region below 0.3).
hov::TransferFunctionSpec BreakpointSpec()
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::RawExtinction;
  spec.Color = { { 0.0, 0.9, 0.2, 0.1 }, { 0.7, 0.1, 0.8, 0.3 }, { 2.0, 0.2, 0.3, 0.9 } };
  spec.Opacity = { { 0.3, 0.0 }, { 0.7, 2.0 }, { 1.2, 0.5 }, { 2.0, 1.5 } };
  return spec;
}

TEST(CurvedSegment, Categorization)
{
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(BreakpointSpec()));
  const auto wm = hov::EmissionModel::WilliamsMax;
  EXPECT_EQ(hov::CategorizeSegment(tf, 0.05, 0.29, wm).Category, SegmentCategory::Empty);
  EXPECT_EQ(hov::CategorizeSegment(tf, 0.05, 0.3, wm).Category, SegmentCategory::Empty);
  const hov::SegmentClassification ps = hov::CategorizeSegment(tf, 0.2, 0.8, wm);
  EXPECT_EQ(ps.Category, SegmentCategory::PiecewiseSmooth);
  EXPECT_EQ(ps.NodeCount, 2); // 0.3 and 0.7
  EXPECT_EQ(hov::CategorizeSegment(tf, 0.75, 1.1, wm).Category, SegmentCategory::Smooth);
  EXPECT_EQ(hov::CategorizeSegment(tf, 2.5, 3.0, wm).Category, SegmentCategory::Smooth); // clamped
  // Occlusion only: black colour with extinction.
  hov::TransferFunctionSpec black = BreakpointSpec();
  for (auto& c : black.Color)
  {
    c.R = c.G = c.B = 0.0;
  }
  hov::TransferFunction tfBlack;
  ASSERT_TRUE(tfBlack.Build(black));
  EXPECT_TRUE(hov::CategorizeSegment(tfBlack, 0.75, 1.1, wm).OcclusionOnly);
  EXPECT_FALSE(hov::CategorizeSegment(tf, 0.75, 1.1, wm).OcclusionOnly);
}

/// Hexahedron of @p order on [0,1]^3 scaled by @p size with geometry x = (r + a s^2, s, t) size.
void MakeHex(hovtest::LagrangeTestCell& cell, int order, double size, double a,
  const std::function<double(const double*)>& fieldOfX)
{
  ASSERT_TRUE(cell.Basis.Initialize(hov::LagrangeShape::Hexahedron, (order + 1) * (order + 1) * (order + 1)));
  const int n = cell.Basis.GetNodeCount();
  cell.Points.resize(3 * n);
  cell.Scalars.resize(n);
  for (int i = 0; i < n; ++i)
  {
    double pc[3];
    cell.Basis.NodeParametricCoords(i, pc);
    double* x = &cell.Points[3 * i];
    x[0] = size * (pc[0] + a * pc[1] * pc[1]);
    x[1] = size * pc[1];
    x[2] = size * pc[2];
    cell.Scalars[i] = fieldOfX(x);
  }
}

struct Outcome
{
  double WorstError = 0.0, WorstOverEstimate = 0.0;
  int Segments = 0, Breakpoints = 0, Curved = 0;
};

/// Every inside interval of random rays, integrated and compared with the reference
/// (the field along the ray given as a polynomial in the ray's length by @p alongRay).
void RunRays(const hovtest::LagrangeTestCell& cell, const hov::TransferFunctionSpec& spec,
  const std::function<hov::Polynomial(const double*, const double*, double)>& alongRay,
  std::mt19937_64& rng, int rays, Outcome& out)
{
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(spec));
  const hov::LagrangeCellView v = cell.View();
  hov::CellDerivativeBounds bounds;
  ASSERT_TRUE(hov::ComputeCellDerivativeBounds(v, bounds));
  hov::CurvedCellFaces faces;
  ASSERT_TRUE(hov::BuildCurvedFaces(v, faces));
  std::normal_distribution<double> n01;
  for (int r = 0; r < rays; ++r)
  {
    double pc[3], x[3], o[3], d[3];
    hovtest::RandomPC(cell.Basis, rng, 0.05, pc);
    hov::EvaluateLagrangePosition(v, pc, x);
    hovtest::RandomRayThrough(x, 3.0, rng, n01, o, d); // unit d: t is length
    hov::CurvedRayInterval iv[8];
    const int count = hov::RayCurvedCellIntervals(v, faces, o, d, 0.0, 6.0, iv, 8);
    for (int i = 0; i < count; ++i)
    {
      const hov::CurvedSegmentResult res =
        hov::IntegrateCurvedSegment(v, bounds, tf, o, d, iv[i].T0, iv[i].T1, iv[i].PC0);
      const double L = iv[i].T1 - iv[i].T0;
      const hov::Polynomial s = alongRay(o, d, iv[i].T0);
      const hovtest::RefRGBA ref = hovtest::ReferencePolynomialRay(
        hovtest::ToReference(spec), s, L, hovtest::RefEmission::WilliamsMax);
      const double err = std::max(std::max(std::abs(res.Color.R - static_cast<double>(ref.R)),
                                    std::abs(res.Color.G - static_cast<double>(ref.G))),
        std::max(std::abs(res.Color.B - static_cast<double>(ref.B)),
          std::abs(res.Color.A - static_cast<double>(ref.A))));
      EXPECT_LE(err, 1e-9) << "ray " << r << " interval " << i << " L " << L << " pieces "
                           << res.Pieces << " category " << static_cast<int>(res.Class.Category);
      EXPECT_TRUE(res.Converged);
      out.WorstError = std::max(out.WorstError, err);
      if (err > 1e-13)
      {
        out.WorstOverEstimate = std::max(out.WorstOverEstimate, err / std::max(res.ErrorEstimate, 1e-300));
      }
      ++out.Segments;
      out.Breakpoints += res.Breakpoints;
      out.Curved += res.ExactField ? 0 : 1;
    }
  }
}

TEST(CurvedSegment, ElvisVerificationFieldOnAnAxisAlignedHexahedron)
{
  std::mt19937_64 rng(121);
  auto field = [](const double* x) { return x[0] * x[0] + x[1] * x[1] + x[2] * x[2]; };
  // s(t) = |o + t d|^2 in the ray's local length tau = t - t0.
  auto alongRay = [](const double* o, const double* d, double t0) {
    double p[3];
    for (int k = 0; k < 3; ++k)
    {
      p[k] = o[k] + t0 * d[k];
    }
    return hov::Polynomial::FromCoefficients({ p[0] * p[0] + p[1] * p[1] + p[2] * p[2],
      2.0 * (p[0] * d[0] + p[1] * d[1] + p[2] * d[2]), d[0] * d[0] + d[1] * d[1] + d[2] * d[2] });
  };
  Outcome out;
  for (int order : { 2, 3 })
  {
    hovtest::LagrangeTestCell cell;
    MakeHex(cell, order, 1.0, 0.0, field);
    RunRays(cell, BreakpointSpec(), alongRay, rng, 25, out);
  }
  hovtest::ReportMeasured("CurvedSegment.ElvisFieldAffineError", out.WorstError);
  std::cout << "[measured] " << out.Segments << " segments, " << out.Breakpoints
            << " breakpoints located, worst error/estimate " << out.WorstOverEstimate << std::endl;
  EXPECT_EQ(out.Curved, 0);
  EXPECT_GT(out.Breakpoints, 0);
}

TEST(CurvedSegment, CurvedHexahedronWithPolynomialInverse)
{
  std::mt19937_64 rng(122);
  const double a = 0.35; // x = r + a s^2: curved faces r = 0, r = 1
  // Field in parametric terms f = (r - 0.3)^2 + 0.5 s + t^3, written through the inverse map.
  auto field = [a](const double* x) {
    const double s = x[1], t = x[2], r = x[0] - a * s * s;
    return (r - 0.3) * (r - 0.3) + 0.5 * s + t * t * t + 0.4;
  };
  auto alongRay = [a](const double* o, const double* d, double t0) {
    // x(tau) = p + tau d: r = px + dx tau - a (py + dy tau)^2, s = py + dy tau, t = pz + dz tau.
    double p[3];
    for (int k = 0; k < 3; ++k)
    {
      p[k] = o[k] + t0 * d[k];
    }
    const hov::Polynomial s = hov::Polynomial::FromCoefficients({ p[1], d[1] });
    const hov::Polynomial t = hov::Polynomial::FromCoefficients({ p[2], d[2] });
    const hov::Polynomial rm = hov::Polynomial::FromCoefficients(
      { p[0] - a * p[1] * p[1] - 0.3, d[0] - 2 * a * p[1] * d[1], -a * d[1] * d[1] });
    hov::Polynomial f; // rm^2 + 0.5 s + t^3 + 0.4
    f.Degree = 4;
    for (int i = 0; i <= 2; ++i)
      for (int j = 0; j <= 2; ++j)
        f.C[i + j] += rm.C[i] * rm.C[j];
    f.C[0] += 0.5 * s.C[0] + t.C[0] * t.C[0] * t.C[0] + 0.4;
    f.C[1] += 0.5 * s.C[1] + 3 * t.C[0] * t.C[0] * t.C[1];
    f.C[2] += 3 * t.C[0] * t.C[1] * t.C[1];
    f.C[3] += t.C[1] * t.C[1] * t.C[1];
    return f;
  };
  hovtest::LagrangeTestCell cell;
  MakeHex(cell, 3, 1.0, a, field);
  Outcome out;
  RunRays(cell, BreakpointSpec(), alongRay, rng, 30, out);
  hovtest::ReportMeasured("CurvedSegment.CurvedHexError", out.WorstError);
  std::cout << "[measured] curved: " << out.Segments << " segments (" << out.Curved
            << " on the curved path), " << out.Breakpoints << " breakpoints, worst error/estimate "
            << out.WorstOverEstimate << std::endl;
  EXPECT_GT(out.Curved, 0);
}

/// LocateBreakpoints on bent cells (tetrahedron P4, hexahedron Q3, wedge
/// (3,3,2); no closed form along the ray): every root of field = level inside
/// each piece is found once and agrees within 1e-11 of the ray length with the
/// root by bisection on the exact field (Newton inversion + shape functions at
/// each probe, independent of the polish).
TEST(CurvedSegment, LocatedBreakpointsAreTheExactRoots)
{
  std::mt19937_64 rng(123);
  auto field = [](const double* x) {
    return 0.7 + 0.3 * std::sin(2.0 * x[0] + 0.5) + 0.2 * x[1] * x[2];
  };
  double worst = 0.0;
  int roots = 0, curvedPieces = 0;
  const hovtest::LagrangeCase cases[] = { { hov::LagrangeShape::Tetra, { 4, 4, 4 }, 0 },
    { hov::LagrangeShape::Hexahedron, { 3, 3, 3 }, 0 },
    { hov::LagrangeShape::Wedge, { 3, 3, 2 }, 0 } };
  for (const hovtest::LagrangeCase& c : cases)
  {
    hovtest::LagrangeTestCell cell;
    ASSERT_TRUE(hovtest::InitBasis(c, cell.Basis));
    hovtest::PlaceNodes(cell, hovtest::RandomMap(rng, 0.12), 0.0, rng, field);
    hov::LagrangeCellView v = cell.View();
    v.Extent = hov::LagrangeCellExtent(v);
    hov::CellDerivativeBounds bounds;
    ASSERT_TRUE(hov::ComputeCellDerivativeBounds(v, bounds));
    hov::CurvedCellFaces faces;
    ASSERT_TRUE(hov::BuildCurvedFaces(v, faces));
    std::normal_distribution<double> n01;
    for (int r = 0; r < 30; ++r)
    {
      double pc[3], x[3], o[3], d[3];
      hovtest::RandomPC(cell.Basis, rng, 0.05, pc);
      hov::EvaluateLagrangePosition(v, pc, x);
      hovtest::RandomRayThrough(x, 3.0, rng, n01, o, d);
      hov::CurvedRayInterval iv[8];
      const int count = hov::RayCurvedCellIntervals(v, faces, o, d, 0.0, 6.0, iv, 8);
      for (int i = 0; i < count; ++i)
      {
        std::vector<hov::FieldPiece> pieces;
        ASSERT_TRUE(hov::RepresentFieldOnSegment(
          v, bounds, o, d, iv[i].T0, iv[i].T1, iv[i].PC0, hov::CurvedSegmentSettings(), pieces));
        // The exact field at o + t d (warm-started inversion along the ray).
        double guess[3] = { iv[i].PC0[0], iv[i].PC0[1], iv[i].PC0[2] };
        auto f = [&](double t) {
          const double y[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
          double q[3] = { guess[0], guess[1], guess[2] };
          EXPECT_TRUE(hov::InvertLagrangeGeometry(v, y, q).Converged());
          std::copy(q, q + 3, guess);
          return hov::EvaluateLagrangeScalar(v, q);
        };
        for (const hov::FieldPiece& piece : pieces)
        {
          curvedPieces += piece.Exact ? 0 : 1;
          for (double level : { 0.55, 0.7, 0.85 })
          {
            std::vector<double> found;
            hov::LocateBreakpoints(v, o, d, piece, level, found);
            // The exact roots: sign changes on a fine grid, then bisection to rounding.
            std::vector<double> exact;
            const int steps = 400;
            const double h = (piece.T1 - piece.T0) / steps;
            double lo = piece.T0, flo = f(lo) - level;
            for (int k = 1; k <= steps; ++k)
            {
              double hi = k == steps ? piece.T1 : piece.T0 + k * h, fhi = f(hi) - level;
              const double nextLo = hi, nextF = fhi;
              if (flo * fhi <= 0 && flo != fhi)
              {
                double a = lo, fa = flo, b = hi;
                for (int it = 0; it < 80 && b - a > 1e-15 * (1.0 + std::abs(a)); ++it)
                {
                  const double mid = 0.5 * (a + b), fm = f(mid) - level;
                  if (fa * fm <= 0)
                  {
                    b = mid;
                  }
                  else
                  {
                    a = mid;
                    fa = fm;
                  }
                }
                exact.push_back(0.5 * (a + b));
              }
              lo = nextLo;
              flo = nextF;
            }
            // Roots where the field only touches the level are not counted;
            // random cells, rays and levels avoid them with probability 1.
            ASSERT_EQ(found.size(), exact.size()) << c.Name() << " ray " << r << " level " << level;
            for (size_t k = 0; k < found.size(); ++k)
            {
              const double err = std::abs(found[k] - exact[k]);
              worst = std::max(worst, err);
              EXPECT_LE(err, 1e-11) << c.Name() << " ray " << r << " level " << level;
              ++roots;
            }
          }
        }
      }
    }
  }
  std::cout << "[measured] LocateBreakpoints: " << roots << " roots in " << curvedPieces
            << " curved pieces, worst |t - bisection root| " << worst << std::endl;
  EXPECT_GT(roots, 30);
  EXPECT_GT(curvedPieces, 30);
}

TEST(CurvedSegment, EmptySegmentsAreExactlyTransparent)
{
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(BreakpointSpec()));
  hovtest::LagrangeTestCell cell;
  // Field in [0, 0.25]: below the first opacity node (0 there).
  MakeHex(cell, 2, 1.0, 0.0, [](const double* x) { return 0.05 + 0.05 * (x[0] + x[1] + x[2]); });
  const hov::LagrangeCellView v = cell.View();
  hov::CellDerivativeBounds bounds;
  ASSERT_TRUE(hov::ComputeCellDerivativeBounds(v, bounds));
  const double o[3] = { -1.0, 0.5, 0.5 }, d[3] = { 1.0, 0.0, 0.0 };
  const hov::CurvedSegmentResult res = hov::IntegrateCurvedSegment(v, bounds, tf, o, d, 1.0, 2.0, nullptr);
  EXPECT_EQ(res.Class.Category, SegmentCategory::Empty);
  EXPECT_EQ(res.Color.A, 0.0);
  EXPECT_EQ(res.Color.R, 0.0);
  EXPECT_EQ(res.Pieces, 0);
}

/// Seconds (best of @p repeats) to integrate @p segments fixed rays through @p cell with @p tf.
double SegmentSeconds(const hovtest::LagrangeTestCell& cell, const hov::TransferFunction& tf,
  int segments, int repeats, std::vector<hov::RGBA>& colors)
{
  const hov::LagrangeCellView v = cell.View();
  hov::CellDerivativeBounds bounds;
  hov::ComputeCellDerivativeBounds(v, bounds);
  double best = 1e300;
  for (int rep = 0; rep < repeats; ++rep)
  {
    colors.clear();
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < segments; ++k)
    {
      const double y = (k + 0.5) / segments;
      const double o[3] = { -1.0, y, 0.5 * y + 0.2 }, d[3] = { 1.0, 0.0, 0.0 };
      colors.push_back(hov::IntegrateCurvedSegment(v, bounds, tf, o, d, 1.0, 2.0, nullptr).Color);
    }
    best = std::min(best,
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

// Issue 21 finding 3: RAY_CAST's cost grew linearly with the table's node
// count even for nodes outside every segment's range (two loops over all
// nodes per segment). 100000 far nodes made each segment ~1000x slower; the
// bound below (5x, best of 5) leaves two orders of magnitude for noise.
TEST(CurvedSegment, FarTableNodesCostNothing)
{
  hovtest::LagrangeTestCell cell;
  MakeHex(cell, 2, 1.0, 0.1, [](const double* x) { return 0.2 + 0.5 * x[0] + 0.3 * x[1] * x[2]; });
  hov::TransferFunction few, many;
  hov::TransferFunctionSpec spec = BreakpointSpec();
  ASSERT_TRUE(few.Build(spec));
  for (int i = 0; i < 100000; ++i)
  {
    spec.Opacity.push_back({ 10.0 + i, 0.5 + 0.25 * (i % 3) });
  }
  ASSERT_TRUE(many.Build(spec));
  std::vector<hov::RGBA> colorsFew, colorsMany;
  const double tFew = SegmentSeconds(cell, few, 200, 5, colorsFew);
  const double tMany = SegmentSeconds(cell, many, 200, 5, colorsMany);
  hovtest::ReportMeasured("CurvedSegment.FarNodesCostRatio", tMany / tFew);
  ASSERT_EQ(colorsFew.size(), colorsMany.size());
  for (size_t k = 0; k < colorsFew.size(); ++k)
  {
    EXPECT_EQ(colorsFew[k].R, colorsMany[k].R) << "segment " << k;
    EXPECT_EQ(colorsFew[k].A, colorsMany[k].A) << "segment " << k;
  }
  EXPECT_LT(tMany, 5.0 * tFew + 1e-3) << "few nodes " << tFew << " s, 100000 far nodes " << tMany;
}
}
