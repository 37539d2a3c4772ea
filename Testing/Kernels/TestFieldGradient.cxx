// Tests of hovFieldGradient's two ray-side functions, each alone:
//  - AffineGradientAlongRay: on every affine shape (tetrahedra, voxels,
//    parallelepiped hexahedra, prismatic wedges and their quadratic forms),
//    with a world-space field the cell reproduces exactly (affine for the
//    linear cells, a full quadric for the quadratic ones), the gradient
//    polynomials along random rays against the analytic gradient evaluated in
//    long double; and d . grad s(tau) against the derivative of the
//    restriction RestrictCellScalar returns (the same field along the ray).
//  - CellFieldAndGradient: on affine cells against the analytic gradient; on
//    non-affine cells (distorted hexahedra, pyramids, the 20-node hexahedron)
//    with the node x-coordinates as the field, whose interpolant IS x(pc), so
//    the gradient is exactly (1, 0, 0); and a general field against central
//    differences of an independent value path (InvertGeometry +
//    InterpolateCellScalar).
//  - Refusals: pyramids, flat cells and non-finite input.

#include "hovFieldGradient.h"

#include "hovCellRestriction.h"
#include "hovCellShapes.h"

#include "hovKernelTestTolerances.h"
#include "hovKernelTestUtilities.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using hovtest::Tolerances;
using hovtest::Worst;
using LD = long double;

namespace
{
/// f(x) = c + g . x + x^T H x (H symmetric), in long double.
struct Quadric
{
  LD C = 0.0L;
  LD G[3] = {};
  LD H[9] = {};

  LD Value(const LD x[3]) const
  {
    LD v = this->C;
    for (int i = 0; i < 3; ++i)
    {
      v += this->G[i] * x[i];
      for (int j = 0; j < 3; ++j)
      {
        v += x[i] * this->H[3 * i + j] * x[j];
      }
    }
    return v;
  }
  void Gradient(const LD x[3], LD out[3]) const
  {
    for (int i = 0; i < 3; ++i)
    {
      out[i] = this->G[i];
      for (int j = 0; j < 3; ++j)
      {
        out[i] += 2.0L * this->H[3 * i + j] * x[j];
      }
    }
  }
  /// Scale of the gradient over |x| <= radius (the error reference).
  double Scale(double radius) const
  {
    LD s = 0.0L;
    for (int i = 0; i < 3; ++i)
    {
      s += std::fabs(this->G[i]);
      for (int j = 0; j < 3; ++j)
      {
        s += 2.0L * std::fabs(this->H[3 * i + j]) * radius;
      }
    }
    return static_cast<double>(s);
  }
};

Quadric RandomQuadric(std::mt19937_64& rng, bool quadratic)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Quadric q;
  q.C = u(rng);
  for (int i = 0; i < 3; ++i)
  {
    q.G[i] = u(rng);
  }
  if (quadratic)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int j = i; j < 3; ++j)
      {
        q.H[3 * i + j] = q.H[3 * j + i] = 0.5 * u(rng);
      }
    }
  }
  return q;
}

/// x = A pc + b, A well conditioned (diagonal for voxels: VTK's voxels are axis aligned).
struct AffineMap
{
  double A[9];
  double B[3];
  void Apply(const double pc[3], double x[3]) const
  {
    for (int i = 0; i < 3; ++i)
    {
      x[i] = this->B[i] + this->A[3 * i] * pc[0] + this->A[3 * i + 1] * pc[1] + this->A[3 * i + 2] * pc[2];
    }
  }
};

AffineMap RandomMap(std::mt19937_64& rng, bool diagonal)
{
  std::uniform_real_distribution<double> u(-0.3, 0.3), s(0.5, 2.0), b(-1.0, 1.0);
  AffineMap m;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      m.A[3 * i + j] = (i == j) ? s(rng) : (diagonal ? 0.0 : u(rng));
    }
    m.B[i] = b(rng);
  }
  return m;
}

void NodePoints(hov::CellShape shape, const AffineMap& map, std::vector<double>& points)
{
  const int n = hov::CellNodeCount(shape);
  points.assign(3 * n, 0.0);
  for (int i = 0; i < n; ++i)
  {
    double pc[3];
    hov::CellNodeParametricCoords(shape, i, pc);
    map.Apply(pc, &points[3 * i]);
  }
}

std::vector<double> SampleField(const Quadric& f, const std::vector<double>& points)
{
  std::vector<double> s(points.size() / 3);
  for (size_t i = 0; i < s.size(); ++i)
  {
    const LD x[3] = { points[3 * i], points[3 * i + 1], points[3 * i + 2] };
    s[i] = static_cast<double>(f.Value(x));
  }
  return s;
}

std::string Name(hov::CellShape shape)
{
  return "shape " + std::to_string(static_cast<int>(shape));
}

bool IsQuadratic(hov::CellShape shape)
{
  return static_cast<int>(shape) >= static_cast<int>(hov::CellShape::QuadraticTetra);
}

const hov::CellShape AffineShapes[] = { hov::CellShape::Tetra, hov::CellShape::Voxel,
  hov::CellShape::Hexahedron, hov::CellShape::Wedge, hov::CellShape::QuadraticTetra,
  hov::CellShape::QuadraticHexahedron, hov::CellShape::QuadraticWedge,
  hov::CellShape::TriQuadraticHexahedron };

/// A ray through the cell: from one interior point toward another.
void RayThrough(hov::CellShape shape, const AffineMap& map, std::mt19937_64& rng, double o[3],
  double d[3])
{
  std::uniform_real_distribution<double> w(0.05, 1.0);
  double p[2][3];
  for (auto& x : p)
  {
    // A random convex combination of the nodes: inside the (convex) cell.
    const int n = hov::CellNodeCount(shape);
    double pc[3] = { 0.0, 0.0, 0.0 }, sum = 0.0;
    for (int i = 0; i < n; ++i)
    {
      double q[3];
      hov::CellNodeParametricCoords(shape, i, q);
      const double wi = w(rng);
      for (int k = 0; k < 3; ++k)
      {
        pc[k] += wi * q[k];
      }
      sum += wi;
    }
    for (double& c : pc)
    {
      c /= sum;
    }
    map.Apply(pc, x);
  }
  for (int k = 0; k < 3; ++k)
  {
    o[k] = p[0][k];
    d[k] = p[1][k] - p[0][k];
  }
}

/**
 * AffineGradientCoefficients (per cell) then AffineGradientAlongLine (per ray)
 * with AffineGradientAlongRay's own inverse Jacobian and parametric line must
 * give its polynomials bit for bit (hov::ShadedCellSegment takes the two steps
 * with the inverse kept per cell); the cached basis must be AffineFieldBasis.
 */
void CheckTwoStepsBitForBit(hov::CellShape shape, const std::vector<double>& points,
  const std::vector<double>& s, const double o[3], const double d[3], double t0,
  const hov::Polynomial expected[3])
{
  std::vector<double> basis(hov::AffineFieldTerms * hov::MaxCellNodes, 0.0);
  ASSERT_TRUE(hov::AffineFieldBasis(shape, basis.data()));
  const double* cached = hov::CachedAffineFieldBasis(shape);
  ASSERT_NE(cached, nullptr);
  for (int i = 0; i < hov::AffineFieldTerms * hov::CellNodeCount(shape); ++i)
  {
    ASSERT_EQ(cached[i], basis[i]) << Name(shape) << " term " << i;
  }
  double coefficients[3][hov::AffineFieldTerms];
  ASSERT_TRUE(hov::AffineGradientCoefficients(shape, s.data(), coefficients));
  double center[3], xc[3], jac[9], inv[9], pc0[3], start[3], step[3];
  hov::CellParametricCenter(shape, center);
  hov::EvaluateGeometry(shape, points.data(), center, xc, jac);
  ASSERT_TRUE(hov::InvertMatrix3(jac, inv));
  hov::CellNodeParametricCoords(shape, 0, pc0);
  for (int i = 0; i < 3; ++i)
  {
    double rel[3];
    for (int k = 0; k < 3; ++k)
    {
      rel[k] = (o[k] - points[k]) + t0 * d[k];
    }
    start[i] = inv[3 * i] * rel[0] + inv[3 * i + 1] * rel[1] + inv[3 * i + 2] * rel[2] + pc0[i];
    step[i] = inv[3 * i] * d[0] + inv[3 * i + 1] * d[1] + inv[3 * i + 2] * d[2];
  }
  hov::Polynomial g[3];
  hov::AffineGradientAlongLine(coefficients, inv, start, step, g);
  for (int a = 0; a < 3; ++a)
  {
    ASSERT_EQ(g[a].Degree, expected[a].Degree) << Name(shape);
    for (int k = 0; k <= g[a].Degree; ++k)
    {
      ASSERT_EQ(g[a].C[k], expected[a].C[k]) << Name(shape) << " component " << a << " term " << k;
    }
  }
}

TEST(FieldGradient, AffineGradientAlongRayMatchesAnalyticGradient)
{
  std::mt19937_64 rng(1901);
  Worst worst, slope;
  for (hov::CellShape shape : AffineShapes)
  {
    for (int trial = 0; trial < 40; ++trial)
    {
      const AffineMap map = RandomMap(rng, shape == hov::CellShape::Voxel);
      std::vector<double> points;
      NodePoints(shape, map, points);
      const Quadric f = RandomQuadric(rng, IsQuadratic(shape));
      const std::vector<double> s = SampleField(f, points);
      double o[3], d[3];
      RayThrough(shape, map, rng, o, d);
      const double t0 = 0.125 * (trial % 5);
      hov::Polynomial g[3];
      ASSERT_TRUE(hov::AffineGradientAlongRay(shape, points.data(), s.data(), o, d, t0, g))
        << Name(shape);
      CheckTwoStepsBitForBit(shape, points, s, o, d, t0, g);
      const double scale = f.Scale(4.0);
      std::vector<hov::RestrictedPiece> pieces;
      hov::CellRestrictionStatus status;
      ASSERT_EQ(hov::RestrictCellScalar(shape, points.data(), s.data(), o, d, t0, 1.0,
                  hov::CellRestrictionSettings(), pieces, &status),
        1)
        << Name(shape);
      ASSERT_TRUE(status.Affine) << Name(shape);
      const hov::Polynomial dS = hov::Derivative(pieces[0].S);
      for (int k = 0; k <= 8; ++k)
      {
        const double tau = (1.0 - t0) * k / 8.0;
        const LD x[3] = { o[0] + (t0 + static_cast<LD>(tau)) * d[0],
          o[1] + (t0 + static_cast<LD>(tau)) * d[1], o[2] + (t0 + static_cast<LD>(tau)) * d[2] };
        LD exact[3];
        f.Gradient(x, exact);
        double dot = 0.0;
        std::ostringstream where;
        where << Name(shape) << " trial " << trial << " tau " << tau;
        for (int i = 0; i < 3; ++i)
        {
          const double gi = hov::Evaluate(g[i], tau);
          ASSERT_TRUE(std::isfinite(gi));
          worst.Add(static_cast<double>(std::fabs(gi - exact[i])) / scale, where.str());
          dot += d[i] * gi;
        }
        // S'(tau) is d/dt of the field: d . grad s.
        const double dScale = scale * (std::fabs(d[0]) + std::fabs(d[1]) + std::fabs(d[2]));
        slope.Add(std::fabs(hov::Evaluate(dS, tau) - dot) / dScale, where.str());
      }
    }
  }
  hovtest::ReportMeasured("AffineGradientAlongRay relative error", worst);
  hovtest::ReportMeasured("S'(tau) vs d . grad s relative", slope);
  EXPECT_LE(worst.Value, Tolerances.FieldGradientRel) << worst.Where;
  EXPECT_LE(slope.Value, Tolerances.FieldGradientRel) << slope.Where;
}

TEST(FieldGradient, CellFieldAndGradientOnAffineCells)
{
  std::mt19937_64 rng(1902);
  Worst worst, value;
  for (hov::CellShape shape : AffineShapes)
  {
    for (int trial = 0; trial < 40; ++trial)
    {
      const AffineMap map = RandomMap(rng, shape == hov::CellShape::Voxel);
      std::vector<double> points;
      NodePoints(shape, map, points);
      const Quadric f = RandomQuadric(rng, IsQuadratic(shape));
      const std::vector<double> s = SampleField(f, points);
      double o[3], d[3];
      RayThrough(shape, map, rng, o, d); // o is an interior point
      double pc[3];
      hov::CellParametricCenter(shape, pc);
      double v = 0.0, g[3];
      ASSERT_TRUE(hov::CellFieldAndGradient(shape, points.data(), s.data(), o, pc, v, g))
        << Name(shape);
      const LD x[3] = { o[0], o[1], o[2] };
      LD exact[3];
      f.Gradient(x, exact);
      const std::string where = Name(shape) + " trial " + std::to_string(trial);
      for (int i = 0; i < 3; ++i)
      {
        worst.Add(static_cast<double>(std::fabs(g[i] - exact[i])) / f.Scale(4.0), where);
      }
      value.Add(static_cast<double>(std::fabs(v - f.Value(x))) / f.Scale(4.0), where);
    }
  }
  hovtest::ReportMeasured("CellFieldAndGradient affine relative error", worst);
  hovtest::ReportMeasured("CellFieldAndGradient value relative error", value);
  EXPECT_LE(worst.Value, Tolerances.FieldGradientRel) << worst.Where;
  EXPECT_LE(value.Value, Tolerances.FieldGradientRel) << value.Where;
}

/// A distorted cell of @p shape: an affine map plus random corner offsets.
std::vector<double> DistortedCell(hov::CellShape shape, std::mt19937_64& rng)
{
  const AffineMap map = RandomMap(rng, false);
  std::vector<double> points;
  const hov::CellShape geometry = hov::GeometryShape(shape);
  NodePoints(geometry, map, points);
  std::uniform_real_distribution<double> jiggle(-0.12, 0.12);
  for (double& p : points)
  {
    p += jiggle(rng);
  }
  if (geometry == shape)
  {
    return points;
  }
  // Higher nodes where the corners' map puts them (the module's geometry is the corners' map).
  std::vector<double> all(3 * hov::CellNodeCount(shape));
  for (int i = 0; i < hov::CellNodeCount(shape); ++i)
  {
    double pc[3];
    hov::CellNodeParametricCoords(shape, i, pc);
    hov::EvaluateGeometry(shape, points.data(), pc, &all[3 * i], nullptr);
  }
  return all;
}

TEST(FieldGradient, CoordinateFieldOnCurvedMapsHasUnitGradient)
{
  // The interpolant of the nodes' x-coordinates is x(pc) itself (the
  // geometry's own shape functions), so its world gradient is exactly e_x.
  std::mt19937_64 rng(1903);
  Worst worst;
  const hov::CellShape shapes[] = { hov::CellShape::Hexahedron, hov::CellShape::Pyramid,
    hov::CellShape::QuadraticHexahedron, hov::CellShape::Wedge };
  for (hov::CellShape shape : shapes)
  {
    for (int trial = 0; trial < 30; ++trial)
    {
      const std::vector<double> points = DistortedCell(shape, rng);
      const int n = hov::CellNodeCount(shape);
      for (int axis = 0; axis < 3; ++axis)
      {
        std::vector<double> s(n);
        for (int i = 0; i < n; ++i)
        {
          s[i] = points[3 * i + axis];
        }
        double pcIn[3] = { 0.3, 0.35, 0.25 }; // inside every shape's domain
        double x[3];
        hov::EvaluateGeometry(shape, points.data(), pcIn, x, nullptr);
        double pc[3];
        hov::CellParametricCenter(shape, pc);
        double v = 0.0, g[3];
        ASSERT_TRUE(hov::CellFieldAndGradient(shape, points.data(), s.data(), x, pc, v, g))
          << Name(shape);
        const std::string where = Name(shape) + " trial " + std::to_string(trial);
        for (int i = 0; i < 3; ++i)
        {
          worst.Add(std::fabs(g[i] - (i == axis ? 1.0 : 0.0)), where);
        }
        worst.Add(std::fabs(v - x[axis]) / (1.0 + std::fabs(x[axis])), where);
      }
    }
  }
  hovtest::ReportMeasured("coordinate field gradient error", worst);
  EXPECT_LE(worst.Value, Tolerances.FieldGradientCurvedAbs) << worst.Where;
}

TEST(FieldGradient, CellFieldAndGradientMatchesCentralDifferences)
{
  std::mt19937_64 rng(1904);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Worst worst;
  const hov::CellShape shapes[] = { hov::CellShape::Hexahedron, hov::CellShape::Pyramid,
    hov::CellShape::QuadraticHexahedron, hov::CellShape::QuadraticPyramid };
  for (hov::CellShape shape : shapes)
  {
    for (int trial = 0; trial < 20; ++trial)
    {
      const std::vector<double> points = DistortedCell(shape, rng);
      std::vector<double> s(hov::CellNodeCount(shape));
      for (double& v : s)
      {
        v = u(rng);
      }
      const double pcIn[3] = { 0.3, 0.3, 0.3 };
      double x[3];
      hov::EvaluateGeometry(shape, points.data(), pcIn, x, nullptr);
      // Independent value path: invert, then interpolate.
      auto value = [&](const double p[3]) {
        double q[3] = { pcIn[0], pcIn[1], pcIn[2] };
        EXPECT_TRUE(hov::InvertGeometry(shape, points.data(), p, q));
        return hov::InterpolateCellScalar(shape, s.data(), q);
      };
      double pc[3];
      hov::CellParametricCenter(shape, pc);
      double v = 0.0, g[3];
      ASSERT_TRUE(hov::CellFieldAndGradient(shape, points.data(), s.data(), x, pc, v, g));
      const double h = 1e-5;
      for (int i = 0; i < 3; ++i)
      {
        double xp[3] = { x[0], x[1], x[2] }, xm[3] = { x[0], x[1], x[2] };
        xp[i] += h;
        xm[i] -= h;
        const double fd = (value(xp) - value(xm)) / (2.0 * h);
        worst.Add(std::fabs(g[i] - fd) / (1.0 + std::fabs(fd)),
          Name(shape) + " trial " + std::to_string(trial));
      }
      EXPECT_NEAR(v, value(x), 1e-12);
    }
  }
  hovtest::ReportMeasured("CellFieldAndGradient vs central differences", worst);
  EXPECT_LE(worst.Value, Tolerances.FieldGradientDifferenceRel) << worst.Where;
}

// A constant field has the gradient (0, 0, 0) exactly, not rounding noise in a
// random direction (shading from noise is noise, and the shaded segment's
// adaptive quadrature never converges on it: hovRobustness case 21001434, a
// quadratic cell with constant scalars, took 8 s for a 24x16 frame); a field
// varying by 1e-9 across the cell keeps its gradient.
TEST(FieldGradient, ConstantFieldHasZeroGradientSmallSlopesStay)
{
  std::mt19937_64 rng(1906);
  std::uniform_real_distribution<double> u(0.1, 0.5), e(-3.0, 6.0);
  const hov::CellShape shapes[] = { hov::CellShape::Hexahedron, hov::CellShape::Pyramid,
    hov::CellShape::QuadraticHexahedron, hov::CellShape::QuadraticPyramid,
    hov::CellShape::QuadraticTetra, hov::CellShape::QuadraticWedge };
  int samples = 0;
  Worst slope;
  for (hov::CellShape shape : shapes)
  {
    for (int trial = 0; trial < 20; ++trial)
    {
      const std::vector<double> points = DistortedCell(shape, rng);
      const int n = hov::CellNodeCount(shape);
      const double c = std::pow(10.0, e(rng)) * (trial % 2 ? -1.0 : 1.0);
      std::vector<double> constant(n, c), tilted(n);
      for (int i = 0; i < n; ++i)
      {
        tilted[i] = 1.0 + 1e-9 * points[3 * i]; // s = 1 + 1e-9 x: gradient (1e-9, 0, 0)
      }
      for (int k = 0; k < 5; ++k, ++samples)
      {
        const double pcIn[3] = { u(rng), u(rng), u(rng) };
        double x[3];
        hov::EvaluateGeometry(shape, points.data(), pcIn, x, nullptr);
        double pc[3] = { pcIn[0], pcIn[1], pcIn[2] }, v = 0.0, g[3];
        ASSERT_TRUE(hov::CellFieldAndGradient(shape, points.data(), constant.data(), x, pc, v, g));
        EXPECT_EQ(g[0], 0.0) << Name(shape) << " trial " << trial;
        EXPECT_EQ(g[1], 0.0) << Name(shape) << " trial " << trial;
        EXPECT_EQ(g[2], 0.0) << Name(shape) << " trial " << trial;
        EXPECT_NEAR(v, c, 1e-14 * std::fabs(c));
        ASSERT_TRUE(hov::CellFieldAndGradient(shape, points.data(), tilted.data(), x, pc, v, g));
        const double err = std::max(std::fabs(g[0] - 1e-9), std::max(std::fabs(g[1]), std::fabs(g[2])));
        slope.Add(err / 1e-9, Name(shape) + " trial " + std::to_string(trial));
      }
    }
  }
  // The gradient polynomials of affine cells along a ray: zero coefficients.
  for (hov::CellShape shape : AffineShapes)
  {
    for (int trial = 0; trial < 20; ++trial, ++samples)
    {
      const AffineMap map = RandomMap(rng, shape == hov::CellShape::Voxel);
      std::vector<double> points;
      NodePoints(shape, map, points);
      const std::vector<double> constant(hov::CellNodeCount(shape), std::pow(10.0, e(rng)));
      double o[3], d[3];
      RayThrough(shape, map, rng, o, d);
      hov::Polynomial g[3];
      ASSERT_TRUE(hov::AffineGradientAlongRay(shape, points.data(), constant.data(), o, d, 0.25, g));
      for (int a = 0; a < 3; ++a)
      {
        for (int k = 0; k <= g[a].Degree; ++k)
        {
          EXPECT_EQ(g[a].C[k], 0.0) << Name(shape) << " trial " << trial;
        }
      }
    }
  }
  hovtest::ReportMeasured("CellFieldAndGradient 1e-9 slope relative error", slope);
  EXPECT_LE(slope.Value, 1e-5) << slope.Where;
  std::cout << "[measured] constant fields: " << samples << " samples, every gradient exactly zero"
            << std::endl;
}

TEST(FieldGradient, RefusesPyramidsFlatCellsAndNonFiniteInput)
{
  std::mt19937_64 rng(1905);
  const double o[3] = { 0.1, 0.1, 0.1 }, d[3] = { 1.0, 0.5, 0.25 };
  hov::Polynomial g[3];
  g[0].Degree = 1;
  g[0].C[1] = 42.0;
  // Pyramids are never affine.
  const AffineMap map = RandomMap(rng, false);
  std::vector<double> points;
  NodePoints(hov::CellShape::Pyramid, map, points);
  std::vector<double> s(5, 1.0);
  EXPECT_FALSE(hov::AffineGradientAlongRay(hov::CellShape::Pyramid, points.data(), s.data(), o, d, 0.0, g));
  double coefficients[3][hov::AffineFieldTerms];
  EXPECT_FALSE(hov::AffineGradientCoefficients(hov::CellShape::Pyramid, s.data(), coefficients));
  EXPECT_EQ(hov::CachedAffineFieldBasis(hov::CellShape::Pyramid), nullptr);
  EXPECT_EQ(hov::CachedAffineFieldBasis(hov::CellShape::QuadraticPyramid), nullptr);
  EXPECT_EQ(hov::CachedAffineFieldBasis(static_cast<hov::CellShape>(7)), nullptr);
  const std::vector<double> nanScalars = { 0.0, NAN, 1.0, 2.0 };
  EXPECT_FALSE(hov::AffineGradientCoefficients(hov::CellShape::Tetra, nanScalars.data(), coefficients));
  EXPECT_EQ(g[0].C[1], 42.0) << "gradient must be untouched on refusal";
  // A flat tetrahedron (all four points in z = 0).
  const double flat[12] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0 };
  const double sv[4] = { 0.0, 1.0, 2.0, 3.0 };
  EXPECT_FALSE(hov::AffineGradientAlongRay(hov::CellShape::Tetra, flat, sv, o, d, 0.0, g));
  double grad[3] = { 7.0, 7.0, 7.0 };
  EXPECT_FALSE(hov::TetraGradient(flat, sv, grad));
  EXPECT_EQ(grad[0], 0.0);
  double pc[3] = { 0.25, 0.25, 0.25 }, v = 0.0;
  const double x[3] = { 0.2, 0.2, 0.0 };
  EXPECT_FALSE(hov::CellFieldAndGradient(hov::CellShape::Tetra, flat, sv, x, pc, v, grad));
  for (double c : grad)
  {
    EXPECT_TRUE(std::isfinite(c));
  }
  // Non-finite scalars or a non-finite ray.
  const double good[12] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  const double bad[4] = { 0.0, std::numeric_limits<double>::quiet_NaN(), 2.0, 3.0 };
  EXPECT_FALSE(hov::AffineGradientAlongRay(hov::CellShape::Tetra, good, bad, o, d, 0.0, g));
  const double infDir[3] = { std::numeric_limits<double>::infinity(), 0.0, 0.0 };
  EXPECT_FALSE(hov::AffineGradientAlongRay(hov::CellShape::Tetra, good, sv, o, infDir, 0.0, g));
  EXPECT_FALSE(hov::TetraGradient(good, bad, grad));
  double pcGood[3] = { 0.25, 0.25, 0.25 };
  const double inside[3] = { 0.2, 0.2, 0.2 };
  EXPECT_FALSE(hov::CellFieldAndGradient(hov::CellShape::Tetra, good, bad, inside, pcGood, v, grad));
  EXPECT_EQ(v, 0.0);
  for (double c : grad)
  {
    EXPECT_EQ(c, 0.0);
  }
  // The good tetrahedron works: s = x + 2y + 3z.
  EXPECT_TRUE(hov::TetraGradient(good, sv, grad));
  EXPECT_DOUBLE_EQ(grad[0], 1.0);
  EXPECT_DOUBLE_EQ(grad[1], 2.0);
  EXPECT_DOUBLE_EQ(grad[2], 3.0);
}
}
