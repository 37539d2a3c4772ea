// The per-ray caster over Lagrange meshes (hovCurvedRayCaster.h) against an
// independent whole-ray reference: meshes of m^3 hexahedra cut from the unit
// cube under a global map with a polynomial inverse (identity, or the curved
// x = X + a Y^2), a field that is a global polynomial of the reference
// coordinates (so every cell reproduces it exactly and the field along any
// ray is one polynomial); the reference finds where the ray is inside the
// mesh by bisection on the reference coordinates and integrates each inside
// interval with hovPolynomialTestSupport's reference. Also: a non-convex
// mesh (one cell removed: rays leave and re-enter), bad cells skipped, faces
// shared by two cells searched once per ray.
#include "hovCurvedRayCaster.h"

#include "hovKernelTestUtilities.h"
#include "hovLagrangeTestSupport.h"
#include "hovPolynomialTestSupport.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <random>

namespace
{
constexpr double A = 0.3; // bend of the curved map

hov::TransferFunctionSpec Spec()
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::RawExtinction;
  spec.Color = { { 0.0, 0.9, 0.2, 0.1 }, { 1.1, 0.1, 0.8, 0.3 }, { 3.0, 0.2, 0.3, 0.9 } };
  spec.Opacity = { { 0.4, 0.0 }, { 1.1, 1.5 }, { 1.9, 0.4 }, { 3.0, 1.2 } };
  return spec;
}

/// Field of the reference coordinates X (a global polynomial of degree <= 2 per direction).
double FieldOfX(const double* X)
{
  return X[0] * X[0] + X[1] * X[1] + X[2] * X[2];
}

/// A mesh of m^3 order-p hexahedra on [0,1]^3 (cell @p removed left out, -1: none), nodes
/// at x = (X + bend Y^2 + shear Y Z, Y, Z) (shear alone: every cell is the trilinear map
/// of its corners); points not shared (each cell has its own) unless @p merge (one point
/// per lattice position: neighbours share their face nodes).
struct TestMesh
{
  std::vector<double> Points, Scalars;
  std::vector<unsigned char> Types;
  std::vector<std::int64_t> Offsets{ 0 }, Connectivity;
  hov::CurvedMeshInput Input() const
  {
    hov::CurvedMeshInput in;
    in.Points = this->Points.data();
    in.NumberOfPoints = static_cast<std::int64_t>(this->Points.size() / 3);
    in.Scalars = this->Scalars.data();
    in.CellTypes = this->Types.data();
    in.Offsets = this->Offsets.data();
    in.Connectivity = this->Connectivity.data();
    in.NumberOfCells = static_cast<std::int64_t>(this->Types.size());
    return in;
  }
};

TestMesh MakeMesh(int m, int p, double bend, int removed, bool merge = false, double shear = 0.0)
{
  TestMesh mesh;
  std::map<std::array<int, 3>, std::int64_t> lattice; // merge: point of each lattice position
  hov::LagrangeBasis b;
  b.Initialize(hov::LagrangeShape::Hexahedron, (p + 1) * (p + 1) * (p + 1));
  for (int c = 0; c < m * m * m; ++c)
  {
    if (c == removed)
    {
      continue;
    }
    const int ci[3] = { c % m, (c / m) % m, c / (m * m) };
    for (int i = 0; i < b.GetNodeCount(); ++i)
    {
      double pc[3], X[3];
      b.NodeParametricCoords(i, pc);
      for (int k = 0; k < 3; ++k)
      {
        X[k] = (ci[k] + pc[k]) / m;
      }
      const std::array<int, 3> key = { ci[0] * p + static_cast<int>(std::lround(pc[0] * p)),
        ci[1] * p + static_cast<int>(std::lround(pc[1] * p)),
        ci[2] * p + static_cast<int>(std::lround(pc[2] * p)) };
      const auto found = lattice.find(key);
      if (merge && found != lattice.end())
      {
        mesh.Connectivity.push_back(found->second);
        continue;
      }
      lattice[key] = static_cast<std::int64_t>(mesh.Scalars.size());
      mesh.Connectivity.push_back(static_cast<std::int64_t>(mesh.Scalars.size()));
      mesh.Points.insert(
        mesh.Points.end(), { X[0] + bend * X[1] * X[1] + shear * X[1] * X[2], X[1], X[2] });
      mesh.Scalars.push_back(FieldOfX(X));
    }
    mesh.Types.push_back(72);
    mesh.Offsets.push_back(static_cast<std::int64_t>(mesh.Connectivity.size()));
  }
  return mesh;
}

/// Reference coordinates along the ray as polynomials of tau = t - t0.
void AlongRay(const double o[3], const double d[3], double t0, double bend, hov::Polynomial X[3],
  double shear = 0.0)
{
  const double p[3] = { o[0] + t0 * d[0], o[1] + t0 * d[1], o[2] + t0 * d[2] };
  X[1] = hov::Polynomial::FromCoefficients({ p[1], d[1] });
  X[2] = hov::Polynomial::FromCoefficients({ p[2], d[2] });
  X[0] = hov::Polynomial::FromCoefficients({ p[0] - bend * p[1] * p[1] - shear * p[1] * p[2],
    d[0] - 2 * bend * p[1] * d[1] - shear * (p[1] * d[2] + p[2] * d[1]),
    -bend * d[1] * d[1] - shear * d[1] * d[2] });
}

/// The whole-ray reference on [0, T] (see file doc).
hovtest::RefRGBA Reference(const double o[3], const double d[3], double T, double bend, int m,
  int removed, const hov::TransferFunctionSpec& spec, double shear = 0.0)
{
  hov::Polynomial X[3];
  AlongRay(o, d, 0.0, bend, X, shear);
  auto inside = [&](long double t) {
    int ci[3];
    for (int k = 0; k < 3; ++k)
    {
      const long double v = hovtest::EvalLd(X[k], t);
      if (v < 0 || v > 1)
      {
        return false;
      }
      ci[k] = std::min(static_cast<int>(v * m), m - 1);
    }
    return ci[0] + m * (ci[1] + m * ci[2]) != removed;
  };
  // Cut points: where any X_k crosses a cell plane k/m (scan + bisection in long double).
  std::vector<long double> cuts{ 0.0L, static_cast<long double>(T) };
  const int grid = 4000;
  for (int k = 0; k < 3; ++k)
  {
    for (int plane = 0; plane <= m; ++plane)
    {
      const long double level = static_cast<long double>(plane) / m;
      long double prevT = 0.0L, prev = hovtest::EvalLd(X[k], 0.0L) - level;
      for (int i = 1; i <= grid; ++i)
      {
        const long double t = static_cast<long double>(T) * i / grid;
        const long double v = hovtest::EvalLd(X[k], t) - level;
        if ((prev < 0) != (v < 0))
        {
          long double a = prevT, b = t;
          for (int it = 0; it < 100; ++it)
          {
            const long double mid = 0.5L * (a + b);
            ((hovtest::EvalLd(X[k], mid) - level < 0) == (prev < 0) ? a : b) = mid;
          }
          cuts.push_back(0.5L * (a + b));
        }
        prevT = t;
        prev = v;
      }
    }
  }
  std::sort(cuts.begin(), cuts.end());
  hovtest::RefRGBA out;
  for (size_t i = 0; i + 1 < cuts.size(); ++i)
  {
    const long double a = cuts[i], b = cuts[i + 1];
    if (!(b > a) || !inside(0.5L * (a + b)))
    {
      continue;
    }
    hov::Polynomial Xa[3];
    AlongRay(o, d, static_cast<double>(a), bend, Xa, shear);
    hov::Polynomial f; // sum of squares of the three (degree <= 4)
    f.Degree = 4;
    for (int k = 0; k < 3; ++k)
      for (int u = 0; u <= Xa[k].Degree; ++u)
        for (int w = 0; w <= Xa[k].Degree; ++w)
          f.C[u + w] += Xa[k].C[u] * Xa[k].C[w];
    const hovtest::RefRGBA seg = hovtest::ReferencePolynomialRay(hovtest::ToReference(spec), f,
      static_cast<double>(b - a), hovtest::RefEmission::WilliamsMax);
    const long double tr = 1.0L - out.A;
    out.R += tr * seg.R;
    out.G += tr * seg.G;
    out.B += tr * seg.B;
    out.A += tr * seg.A;
  }
  return out;
}

/// Random rays through the mesh: caster vs reference; returns the worst error.
double CompareRays(const TestMesh& mesh, int m, double bend, int removed, int rays,
  std::mt19937_64& rng, double shear = 0.0, int* trilinear = nullptr)
{
  hov::CurvedRayCaster caster;
  std::string msg;
  EXPECT_TRUE(caster.Build(mesh.Input(), &msg)) << msg;
  if (trilinear)
  {
    *trilinear = caster.GetNumberOfTrilinearCells();
  }
  hov::TransferFunction tf;
  EXPECT_TRUE(tf.Build(Spec()));
  std::uniform_real_distribution<double> u(0.05, 0.95);
  std::normal_distribution<double> n01;
  double worst = 0.0;
  int segments = 0;
  for (int r = 0; r < rays; ++r)
  {
    const double X[3] = { u(rng), u(rng), u(rng) };
    const double x[3] = { X[0] + bend * X[1] * X[1] + shear * X[1] * X[2], X[1], X[2] };
    double o[3], d[3];
    hovtest::RandomRayThrough(x, 3.0, rng, n01, o, d);
    double err = 0.0;
    hov::CurvedRayStats stats;
    const hov::RGBA got = caster.TraceRay(o, d, 0.0, 6.0, tf, {}, &err, &stats);
    const hovtest::RefRGBA ref = Reference(o, d, 6.0, bend, m, removed, Spec(), shear);
    const double e = std::max(std::max(std::abs(got.R - static_cast<double>(ref.R)),
                                std::abs(got.G - static_cast<double>(ref.G))),
      std::max(std::abs(got.B - static_cast<double>(ref.B)), std::abs(got.A - static_cast<double>(ref.A))));
    EXPECT_LE(e, 1e-9) << "ray " << r << " segments " << stats.Segments;
    EXPECT_TRUE(stats.Converged);
    worst = std::max(worst, e);
    segments += stats.Segments;
  }
  std::cout << "[measured] " << rays << " rays, " << segments << " segments, worst RGBA error "
            << worst << std::endl;
  return worst;
}

TEST(CurvedRayCaster, AffineMeshMatchesWholeRayReference)
{
  std::mt19937_64 rng(131);
  const TestMesh mesh = MakeMesh(2, 2, 0.0, -1);
  hovtest::ReportMeasured("CurvedRayCaster.AffineError", CompareRays(mesh, 2, 0.0, -1, 12, rng));
}

TEST(CurvedRayCaster, CurvedMeshMatchesWholeRayReference)
{
  std::mt19937_64 rng(132);
  const TestMesh mesh = MakeMesh(2, 3, A, -1);
  hovtest::ReportMeasured("CurvedRayCaster.CurvedError", CompareRays(mesh, 2, A, -1, 12, rng));
}

// Order-3 hexahedra whose nodes lie on the trilinear map of their corners
// (x = X + a Y Z): detected as trilinear (geometry from the 8 corners, faces
// as bilinear patches), the same image as the reference.
TEST(CurvedRayCaster, TrilinearHexahedraMatchWholeRayReference)
{
  std::mt19937_64 rng(137);
  const TestMesh mesh = MakeMesh(2, 3, 0.0, -1, false, A);
  int trilinear = 0;
  hovtest::ReportMeasured(
    "CurvedRayCaster.TrilinearError", CompareRays(mesh, 2, 0.0, -1, 12, rng, A, &trilinear));
  EXPECT_EQ(trilinear, 8);
  // The bent map (x = X + a Y^2) is not trilinear: no cell takes that path.
  hov::CurvedRayCaster bent;
  ASSERT_TRUE(bent.Build(MakeMesh(2, 3, A, -1).Input()));
  EXPECT_EQ(bent.GetNumberOfTrilinearCells(), 0);
}

TEST(CurvedRayCaster, NonConvexMeshRaysReenter)
{
  std::mt19937_64 rng(133);
  const int removed = 7; // the (1,1,1) corner cell
  const TestMesh mesh = MakeMesh(2, 2, A, removed);
  hovtest::ReportMeasured("CurvedRayCaster.NonConvexError", CompareRays(mesh, 2, A, removed, 12, rng));
}

TEST(CurvedRayCaster, BadCellsAreSkippedTheRestRenders)
{
  TestMesh mesh = MakeMesh(2, 2, 0.0, -1);
  hov::CurvedRayCaster good;
  ASSERT_TRUE(good.Build(mesh.Input()));
  // Append a Lagrange pyramid (74) and a hexahedron with 11 nodes, both reusing points.
  for (int type : { 74, 72 })
  {
    for (int i = 0; i < (type == 74 ? 5 : 11); ++i)
    {
      mesh.Connectivity.push_back(i);
    }
    mesh.Types.push_back(static_cast<unsigned char>(type));
    mesh.Offsets.push_back(static_cast<std::int64_t>(mesh.Connectivity.size()));
  }
  hov::CurvedRayCaster caster;
  std::string msg;
  ASSERT_TRUE(caster.Build(mesh.Input(), &msg));
  EXPECT_EQ(caster.GetNumberOfSkippedCells(), 2);
  EXPECT_NE(msg.find("74"), std::string::npos) << msg;
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(Spec()));
  const double o[3] = { -1.0, 0.3, 0.6 }, d[3] = { 1.0, 0.1, 0.05 };
  const hov::RGBA a = caster.TraceRay(o, d, 0.0, 5.0, tf, {});
  const hov::RGBA b = good.TraceRay(o, d, 0.0, 5.0, tf, {});
  EXPECT_EQ(a.R, b.R);
  EXPECT_EQ(a.A, b.A);
  EXPECT_GT(a.A, 0.0);
}
}

namespace
{
/// Largest |channel| difference between the caster's and the reference's RGBA.
double RGBAError(const hov::RGBA& got, const hovtest::RefRGBA& ref)
{
  return std::max(std::max(std::abs(got.R - static_cast<double>(ref.R)),
                    std::abs(got.G - static_cast<double>(ref.G))),
    std::max(std::abs(got.B - static_cast<double>(ref.B)), std::abs(got.A - static_cast<double>(ref.A))));
}

/// A curved 4^3 mesh, its caster and the table.
struct FourCubed
{
  static constexpr int M = 4;
  TestMesh Mesh = MakeMesh(M, 2, A, -1);
  hov::CurvedRayCaster Caster;
  hov::TransferFunction Tf;
  FourCubed()
  {
    EXPECT_TRUE(this->Caster.Build(this->Mesh.Input()));
    EXPECT_TRUE(this->Tf.Build(Spec()));
  }
};
}

// Rays lying in faces shared by two cells (y = 1/2) and on edges shared by
// four (y = z = 1/2, y = 1/4 and z = 3/4), along the mesh's x axis through
// all four cells of a row: each part of the ray counted once (before the fix,
// the face ray had 8 segments and opacity 0.80 instead of 0.55).
TEST(CurvedRayCaster, RaysInSharedFacesAndEdgesCountOnce)
{
  FourCubed s;
  const double yz[][2] = { { 0.5, 0.52 }, { 0.5, 0.5 }, { 0.25, 0.75 }, { 0.31, 0.5 } };
  double worst = 0.0;
  for (const auto& p : yz)
  {
    const double o[3] = { -1.0 + A * p[0] * p[0], p[0], p[1] }, d[3] = { 1.0, 0.0, 0.0 };
    hov::CurvedRayStats stats;
    const hov::RGBA got = s.Caster.TraceRay(o, d, 0.0, 6.0, s.Tf, {}, nullptr, &stats);
    const double e = RGBAError(got, Reference(o, d, 6.0, A, FourCubed::M, -1, Spec()));
    EXPECT_LE(e, 1e-9) << "y " << p[0] << " z " << p[1] << ": " << stats.Segments << " segments";
    EXPECT_EQ(stats.Segments, FourCubed::M) << "y " << p[0] << " z " << p[1];
    worst = std::max(worst, e);
  }
  hovtest::ReportMeasured("CurvedRayCaster.SharedFaceRayError", worst);
}

// Faces shared by two cells are searched once per ray (hovCurvedSharedFaces.h):
// on a curved 3^3 mesh whose cells share their face nodes (a corner cell
// removed: rays leave and re-enter), every interior face is linked, random
// rays and rays in shared faces and edges match the whole-ray reference, and
// the image equals the one without sharing to rounding.
TEST(CurvedRayCaster, SharedFacesAreSearchedOnce)
{
  const int m = 3, removed = 0;
  const TestMesh mesh = MakeMesh(m, 3, A, removed, true);
  hov::CurvedRayCaster shared, separate;
  separate.SetShareFaces(false);
  ASSERT_TRUE(shared.Build(mesh.Input()));
  ASSERT_TRUE(separate.Build(mesh.Input()));
  EXPECT_EQ(shared.GetNumberOfSharedFaces(), 3 * m * m * (m - 1) - 3);
  EXPECT_EQ(separate.GetNumberOfSharedFaces(), 0);
  // Without merged points no face is shared.
  hov::CurvedRayCaster apart;
  ASSERT_TRUE(apart.Build(MakeMesh(m, 3, A, removed).Input()));
  EXPECT_EQ(apart.GetNumberOfSharedFaces(), 0);
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(Spec()));
  std::mt19937_64 rng(141);
  std::uniform_real_distribution<double> u(0.05, 0.95);
  std::normal_distribution<double> n01;
  double worstRef = 0.0, worstPair = 0.0;
  auto check = [&](const double o[3], const double d[3], const char* what) {
    const hov::RGBA a = shared.TraceRay(o, d, 0.0, 6.0, tf, {});
    const hov::RGBA b = separate.TraceRay(o, d, 0.0, 6.0, tf, {});
    const double eRef = RGBAError(a, Reference(o, d, 6.0, A, m, removed, Spec()));
    const double ePair = std::max({ std::abs(a.R - b.R), std::abs(a.G - b.G),
      std::abs(a.B - b.B), std::abs(a.A - b.A) });
    EXPECT_LE(eRef, 1e-9) << what;
    EXPECT_LE(ePair, 1e-12) << what;
    worstRef = std::max(worstRef, eRef);
    worstPair = std::max(worstPair, ePair);
  };
  for (int r = 0; r < 40; ++r)
  {
    const double X[3] = { u(rng), u(rng), u(rng) };
    const double x[3] = { X[0] + A * X[1] * X[1], X[1], X[2] };
    double o[3], d[3];
    hovtest::RandomRayThrough(x, 3.0, rng, n01, o, d);
    check(o, d, "random ray");
  }
  // Rays in the shared faces y = 1/3 and on the shared edge y = z = 2/3, along x.
  const double yz[][2] = { { 1.0 / 3, 0.52 }, { 2.0 / 3, 2.0 / 3 } };
  for (const auto& p : yz)
  {
    const double o[3] = { -1.0 + A * p[0] * p[0], p[0], p[1] }, d[3] = { 1.0, 0.0, 0.0 };
    check(o, d, "ray in a shared face or edge");
  }
  std::cout << "[measured] shared faces: " << shared.GetNumberOfSharedFaces()
            << ", worst RGBA error against the reference " << worstRef
            << ", against the caster without sharing " << worstPair << std::endl;
}

// The tolerance is per pixel (per ray), not per segment: on the curved 4^3
// mesh (up to ~10 segments per ray) every ray's error against the whole-ray
// reference and its summed error estimate stay within the tolerance; rays
// integrated again with tighter segment tolerances are counted (at 1e-8 one
// of 16 is: its first sum of estimates exceeded the tolerance).
TEST(CurvedRayCaster, ToleranceHoldsPerRay)
{
  FourCubed s;
  for (double tol : { 1e-2, 1e-5, 1e-8, 1e-10 })
  {
    std::mt19937_64 rng(140);
    std::uniform_real_distribution<double> u(0.05, 0.95);
    std::normal_distribution<double> n01;
    hov::CurvedSegmentSettings settings;
    settings.Quadrature.Tolerance = tol;
    double worst = 0.0, worstEstimate = 0.0;
    int segments = 0, retried = 0;
    const int rays = 16;
    for (int r = 0; r < rays; ++r)
    {
      double o[3], d[3];
      if (r < 10) // random directions through random inside points
      {
        const double X[3] = { u(rng), u(rng), u(rng) };
        const double x[3] = { X[0] + A * X[1] * X[1], X[1], X[2] };
        hovtest::RandomRayThrough(x, 3.0, rng, n01, o, d);
      }
      else // along x through a whole row: four segments of similar error
      {
        const double y = 0.11 + 0.13 * (r - 10) + 0.01, z = 0.07 + 0.15 * (r - 10);
        o[0] = -1.0 + A * y * y;
        o[1] = y;
        o[2] = z;
        d[0] = 1.0;
        d[1] = d[2] = 0.0;
      }
      double est = 0.0;
      hov::CurvedRayStats stats;
      const hov::RGBA got = s.Caster.TraceRay(o, d, 0.0, 6.0, s.Tf, settings, &est, &stats);
      const double e = RGBAError(got, Reference(o, d, 6.0, A, FourCubed::M, -1, Spec()));
      EXPECT_LE(e, tol) << "ray " << r << " segments " << stats.Segments;
      EXPECT_LE(est, tol) << "ray " << r;
      EXPECT_GE(stats.TolerancePasses, 1);
      worst = std::max(worst, e);
      worstEstimate = std::max(worstEstimate, est);
      segments += stats.Segments;
      retried += stats.TolerancePasses > 1 ? 1 : 0;
    }
    std::cout << "[measured] tolerance " << tol << ": " << rays << " rays, " << segments
              << " segments, worst error " << worst << ", worst estimate " << worstEstimate
              << ", rays integrated again " << retried << std::endl;
  }
}
