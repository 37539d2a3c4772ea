// The general-scalar reference of hovTestReferenceGeneral.h checked on its
// own (no mapper involved), before the acceptance tests rely on it:
//  1. a linear s(t) through the general path equals the linear reference
//     IntegrateRay (hovTestReference.h: exact optical depth per piece), all
//     three opacity semantics and both emission models: |diff| <= 1e-12;
//  2. BreakTimes finds a quadratic's node crossings (closed form) to 1e-15 and
//     its interior extremum to 1e-9 (Brent), also for an extremum 0.5 % from the front;
//  3. a quadratic and a cubic s(t) against the brute-force midpoint sum
//     (4e5 steps, error O(1e-10)): <= 1e-8; composition [0,a] + [a,L] = [0,L]
//     to 1e-12;
//  4. the cell fields: a quadratic tetrahedron with the nodal values of a
//     quadratic f reproduces f; a distorted hexahedron with the nodal values
//     of a linear f reproduces f (checks the Newton inversion); an
//     axis-aligned box reproduces a trilinear f: all to 1e-13;
//  5. the 1 -> 8^k subdivision of a quadratic-tet block: 8^k cells per cell,
//     (n 2^k + 1)^3 points (conforming), total volume, and a quadratic field's
//     values at the new nodes.
#include "hovTestReferenceGeneral.h"
#include "hovTestScenes.h"

#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <iostream>
#include <random>

using hovTestRef::Real;
using namespace hovTest;

namespace
{
double MaxDiff(const hovTestRef::RGBA& a, const hovTestRef::RGBA& b)
{
  double m = 0;
  for (int c = 0; c < 4; ++c)
  {
    m = std::max(m, static_cast<double>(std::fabs(a[c] - b[c])));
  }
  return m;
}

/// Colour and opacity nodes at different positions, opacity < 1 (GPU semantics).
void SeveralNodesTF(TF& tf)
{
  tf.Color->AddRGBPoint(0.0, 0.1, 0.3, 0.9);
  tf.Color->AddRGBPoint(0.35, 0.9, 0.2, 0.3);
  tf.Color->AddRGBPoint(0.7, 0.2, 0.9, 0.4);
  tf.Color->AddRGBPoint(1.2, 1.0, 1.0, 0.2);
  tf.Opacity->AddPoint(0.0, 0.05);
  tf.Opacity->AddPoint(0.2, 0.6);
  tf.Opacity->AddPoint(0.5, 0.15);
  tf.Opacity->AddPoint(0.8, 0.9);
  tf.Opacity->AddPoint(1.2, 0.3);
  tf.Property->SetScalarOpacityUnitDistance(0.6);
}

double Quadratic(const double* x)
{
  return 0.3 + 0.4 * x[0] - 0.2 * x[1] + 0.5 * x[2] + 0.7 * x[0] * x[0] - 0.3 * x[1] * x[2] +
    0.6 * x[2] * x[2];
}
}

int TestQuadraticReference(int, char*[])
{
  Checker ck;
  TF tf;
  SeveralNodesTF(tf);
  vtkVolumeProperty* prop = tf.Property;

  // 1. Linear s through both references.
  double worst = 0;
  const double lines[][3] = { { 0.1, 1.1, 1.3 }, { 1.15, -0.05, 0.7 }, { 0.42, 0.42, 2.0 },
    { 0.25, 0.3, 0.01 }, { 0.0, 1.2, 4.0 } };
  for (int sem = 0; sem < 3; ++sem)
  {
    for (int em = 0; em < 2; ++em)
    {
      const hovTestRef::Model model{ sem, em, 0.8 };
      for (const auto& l : lines)
      {
        const Real L = l[2];
        auto s = [&](Real t) { return l[0] + (Real(l[1]) - l[0]) * t / L; };
        const auto g = hovTestRef::IntegrateRayGeneral(prop, model, s, L);
        const auto r = hovTestRef::IntegrateRay(prop, model, l[0], l[1], L);
        worst = std::max(worst, MaxDiff(g, r));
      }
    }
  }
  ck.Check(worst <= 1e-12,
    "1. general path == linear reference on linear s, all semantics/emissions: max |diff| " +
      Fmt(worst) + " <= 1e-12");

  // 2. Break times of s(t) = 0.9 - 2 (t - 0.4)^2 and of (t - 0.005)^2.
  {
    auto s = [](Real t) { return Real(0.9) - 2 * (t - Real(0.4)) * (t - Real(0.4)); };
    hovTestRef::GeneralStats st;
    const auto cuts = hovTestRef::BreakTimes(s, 1, { 0.6, 0.85, 2.0 }, 64, &st);
    const Real want[] = { 0, Real(0.4) - std::sqrt(Real(0.15)), Real(0.4) - std::sqrt(Real(0.025)),
      Real(0.4), Real(0.4) + std::sqrt(Real(0.025)), Real(0.4) + std::sqrt(Real(0.15)), 1 };
    // Crossings to long double precision; the extremum (Brent) to ~sqrt(eps).
    double err = cuts.size() == 7 ? 0 : 1, errExtremum = err;
    for (size_t k = 0; k < cuts.size() && cuts.size() == 7; ++k)
    {
      const double e = static_cast<double>(std::fabs(cuts[k] - want[k]));
      (k == 3 ? errExtremum : err) = std::max(k == 3 ? errExtremum : err, e);
    }
    ck.Check(err <= 1e-15 && errExtremum <= 1e-9 && st.Extrema == 1 && st.Crossings == 4,
      "2. quadratic with interior maximum: " + std::to_string(cuts.size()) +
        " cuts (want 7), crossings max error " + Fmt(err) + ", extremum error " + Fmt(errExtremum));
    auto e = [](Real t) { return (t - Real(0.005)) * (t - Real(0.005)); };
    const auto cuts2 = hovTestRef::BreakTimes(e, 1, { 1e-6 }, 64);
    const bool ok = cuts2.size() == 5 && std::fabs(cuts2[1] - Real(0.004)) < 1e-15 &&
      std::fabs(cuts2[2] - Real(0.005)) < 1e-9 && std::fabs(cuts2[3] - Real(0.006)) < 1e-15;
    ck.Check(ok, "2. minimum 0.5% from the front, node just above it: both crossings found (" +
        std::to_string(cuts2.size()) + " cuts, want 5)");
  }

  // 3. Non-linear s against the brute force; composition.
  {
    double worstBF = 0, worstComp = 0;
    const Real L = 1.7;
    const hovTestRef::ScalarFunction fields[] = {
      [&](Real t) { return Real(0.05) + Real(1.1) * t / L * (2 - t / L) * Real(1.05); },
      [&](Real t) {
        const Real x = t / L;
        return Real(0.6) + Real(2.2) * x * (x - Real(0.3)) * (x - Real(0.8));
      },
    };
    for (const auto& s : fields)
    {
      for (int sem = 0; sem < 3; ++sem)
      {
        const hovTestRef::Model model{ sem, sem == 2 ? 1 : 0, 0.8 };
        const auto g = hovTestRef::IntegrateRayGeneral(prop, model, s, L);
        const auto b = hovTestRef::IntegrateRayGeneralBruteForce(prop, model, s, L, 400000);
        worstBF = std::max(worstBF, MaxDiff(g, b));
        const Real a = 0.77;
        const auto front = hovTestRef::IntegrateRayGeneral(prop, model, s, a);
        const auto back = hovTestRef::IntegrateRayGeneral(
          prop, model, [&](Real t) { return s(t + a); }, L - a);
        hovTestRef::RGBA comp;
        comp.R = front.R + (1 - front.A) * back.R;
        comp.G = front.G + (1 - front.A) * back.G;
        comp.B = front.B + (1 - front.A) * back.B;
        comp.A = front.A + (1 - front.A) * back.A;
        worstComp = std::max(worstComp, MaxDiff(g, comp));
      }
    }
    ck.Check(worstBF <= 1e-8,
      "3. quadratic and cubic s vs brute force (4e5 steps): max |diff| " + Fmt(worstBF) + " <= 1e-8");
    ck.Check(worstComp <= 1e-12,
      "3. [0,a] composited with [a,L] == [0,L]: max |diff| " + Fmt(worstComp) + " <= 1e-12");
  }

  // 4. Cell fields.
  {
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const double tet[4][3] = { { 0.1, 0.0, -0.1 }, { 1.3, 0.2, 0.1 }, { 0.2, 1.1, 0.3 },
      { 0.4, 0.3, 1.2 } };
    const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
    double nodes[10][3], s[10];
    for (int i = 0; i < 10; ++i)
    {
      for (int a = 0; a < 3; ++a)
      {
        nodes[i][a] = i < 4 ? tet[i][a] : (tet[edges[i - 4][0]][a] + tet[edges[i - 4][1]][a]) / 2;
      }
      s[i] = Quadratic(nodes[i]);
    }
    const hovTestRef::QuadraticTetraField qf(tet, s);
    const double hex[8][3] = { { 0, 0, 0 }, { 1.2, 0.1, 0 }, { 1.1, 0.9, 0.1 }, { -0.1, 1.0, 0 },
      { 0.1, 0.0, 1.0 }, { 0.9, 0.2, 1.1 }, { 1.0, 1.1, 0.9 }, { 0.1, 0.8, 1.2 } };
    auto lin = [](const double* x) { return 0.2 + 0.7 * x[0] - 0.4 * x[1] + 1.1 * x[2]; };
    double hs[8], bs[8];
    const double box[8][3] = { { 0, 0, 0 }, { 2, 0, 0 }, { 2, 1, 0 }, { 0, 1, 0 }, { 0, 0, 3 },
      { 2, 0, 3 }, { 2, 1, 3 }, { 0, 1, 3 } };
    auto tri = [](const double* x) {
      return 0.1 + x[0] - 0.5 * x[1] + 0.3 * x[2] + 0.8 * x[0] * x[1] - 0.2 * x[1] * x[2] +
        0.4 * x[0] * x[2] + 0.6 * x[0] * x[1] * x[2];
    };
    for (int i = 0; i < 8; ++i)
    {
      hs[i] = lin(hex[i]);
      bs[i] = tri(box[i]);
    }
    const hovTestRef::HexahedronField hf(hex, hs), bf(box, bs);
    double eq = 0, eh = 0, eb = 0;
    for (int k = 0; k < 200; ++k)
    {
      double w[4] = { u01(rng), u01(rng), u01(rng), u01(rng) };
      const double sum = w[0] + w[1] + w[2] + w[3];
      double x[3] = { 0, 0, 0 }, xb[3], xh[3] = { 0, 0, 0 };
      const double p[3] = { u01(rng), u01(rng), u01(rng) };
      for (int a = 0; a < 3; ++a)
      {
        for (int v = 0; v < 4; ++v)
        {
          x[a] += w[v] / sum * tet[v][a];
        }
        xb[a] = p[a] * (a == 0 ? 2 : a == 1 ? 1 : 3);
      }
      // A point of the distorted hexahedron: its trilinear map at p.
      const double N[8] = { (1 - p[0]) * (1 - p[1]) * (1 - p[2]), p[0] * (1 - p[1]) * (1 - p[2]),
        p[0] * p[1] * (1 - p[2]), (1 - p[0]) * p[1] * (1 - p[2]), (1 - p[0]) * (1 - p[1]) * p[2],
        p[0] * (1 - p[1]) * p[2], p[0] * p[1] * p[2], (1 - p[0]) * p[1] * p[2] };
      for (int v = 0; v < 8; ++v)
      {
        for (int a = 0; a < 3; ++a)
        {
          xh[a] += N[v] * hex[v][a];
        }
      }
      eq = std::max(eq, static_cast<double>(std::fabs(qf({ x[0], x[1], x[2] }) - Quadratic(x))));
      eh = std::max(eh, static_cast<double>(std::fabs(hf({ xh[0], xh[1], xh[2] }) - lin(xh))));
      eb = std::max(eb, static_cast<double>(std::fabs(bf({ xb[0], xb[1], xb[2] }) - tri(xb))));
    }
    ck.Check(eq <= 1e-13, "4. quadratic tetrahedron field reproduces a quadratic: " + Fmt(eq));
    ck.Check(eh <= 1e-13, "4. distorted hexahedron (Newton) reproduces a linear f: " + Fmt(eh));
    ck.Check(eb <= 1e-13, "4. box hexahedron reproduces a trilinear f: " + Fmt(eb));
  }

  // 5. Subdivision.
  {
    const double origin[3] = { -0.5, 0.25, 0.0 };
    auto block = hovTestRef::MakeQuadraticTetraBlock(2, origin, 1.5, Quadratic);
    for (int levels = 0; levels <= 2; ++levels)
    {
      auto sub = hovTestRef::SubdivideQuadraticTetras(block, levels);
      const vtkIdType side = 2 * (1 << levels) + 1;
      double total = 0, minVol = 1e300;
      for (vtkIdType c = 0; c < sub->GetNumberOfCells(); ++c)
      {
        const vtkIdType* ids;
        vtkIdType npts;
        sub->GetCellPoints(c, npts, ids);
        double x[4][3];
        for (int v = 0; v < 4; ++v)
        {
          sub->GetPoint(ids[v], x[v]);
        }
        double e[3][3];
        for (int v = 0; v < 3; ++v)
        {
          for (int a = 0; a < 3; ++a)
          {
            e[v][a] = x[v + 1][a] - x[0][a];
          }
        }
        const double vol = (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                             e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                             e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) / 6;
        total += vol;
        minVol = std::min(minVol, vol);
      }
      double err = 0;
      vtkDataArray* sv = sub->GetPointData()->GetScalars();
      for (vtkIdType p = 0; p < sub->GetNumberOfPoints(); ++p)
      {
        err = std::max(err, std::fabs(sv->GetComponent(p, 0) - Quadratic(sub->GetPoint(p))));
      }
      ck.Check(sub->GetNumberOfCells() == 48 * (vtkIdType(1) << (3 * levels)) &&
          sub->GetNumberOfPoints() == side * side * side && std::fabs(total - 3.375) < 1e-12 &&
          minVol > 0 && err < 1e-13,
        "5. subdivision level " + std::to_string(levels) + ": " +
          std::to_string(sub->GetNumberOfCells()) + " tets, " +
          std::to_string(sub->GetNumberOfPoints()) + " points (want " +
          std::to_string(side * side * side) + "), volume " + Fmt(total) +
          " (want 3.375), min volume " + Fmt(minVol) + ", field error " + Fmt(err));
    }
  }
  return ck.Result();
}
