// The Lagrange kernels on the two real curved datasets (Testing/Data,
// copied from the shared collection: gmsh order-4 meshes, dolfinx fields):
// platehole_lagrange_hex_q4.vtu (192 hexahedra, type 72, HigherOrderDegrees)
// and tjunction_lagrange_tet_p4.vtu (3790 tetrahedra, type 71).
//  - Volume: sum over cells of the Gauss-Legendre quadrature of det J of our
//    geometry map (exact for these polynomial integrands: 8 points per
//    direction; tetrahedra through the Duffy map) against the reference
//    volumes of the collection's manifest (dolfinx quadrature on the curved
//    cells: 0.09509126148 and 3.65787548); the straight-sided (linearised)
//    volumes 0.095092138 and 3.6523358 differ by 9e-6 and 1.5e-3 relative.
//  - Inversion: x(pc) -> pc round trips at random points of every cell.
//  - Ray casting (hovCurvedRayCaster): a small orthographic image of each:
//    finite, 0 <= alpha <= 1, error estimates below ElVis's pixel-exact
//    0.001; time per ray printed (not checked).
#include "hovCurvedRayCaster.h"
#include "hovLagrangeCell.h"
#include "hovTransferFunction.h"

#include "hovTestReferenceDatasets.h"
#include "hovTestScenes.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <vector>

using namespace hovTest;

namespace
{
/// The grid's arrays in the caster's layout (64-bit copies).
struct MeshArrays
{
  std::vector<double> Points, Scalars;
  std::vector<unsigned char> Types;
  std::vector<std::int64_t> Offsets, Connectivity;
  std::vector<int> Degrees;
  hov::CurvedMeshInput Input() const
  {
    hov::CurvedMeshInput in;
    in.Points = this->Points.data();
    in.NumberOfPoints = static_cast<std::int64_t>(this->Scalars.size());
    in.Scalars = this->Scalars.data();
    in.CellTypes = this->Types.data();
    in.Offsets = this->Offsets.data();
    in.Connectivity = this->Connectivity.data();
    in.NumberOfCells = static_cast<std::int64_t>(this->Types.size());
    in.Degrees = this->Degrees.empty() ? nullptr : this->Degrees.data();
    return in;
  }
};

MeshArrays Convert(vtkUnstructuredGrid* grid)
{
  MeshArrays m;
  const vtkIdType np = grid->GetNumberOfPoints(), nc = grid->GetNumberOfCells();
  vtkDataArray* s = grid->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < np; ++i)
  {
    double x[3];
    grid->GetPoint(i, x);
    m.Points.insert(m.Points.end(), x, x + 3);
    m.Scalars.push_back(s ? s->GetComponent(i, 0) : 0.0);
  }
  vtkDataArray* degrees = grid->GetCellData()->GetHigherOrderDegrees();
  m.Offsets.push_back(0);
  for (vtkIdType c = 0; c < nc; ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    grid->GetCellPoints(c, n, ids);
    m.Connectivity.insert(m.Connectivity.end(), ids, ids + n);
    m.Offsets.push_back(static_cast<std::int64_t>(m.Connectivity.size()));
    m.Types.push_back(static_cast<unsigned char>(grid->GetCellType(c)));
    for (int k = 0; degrees && k < 3; ++k)
    {
      m.Degrees.push_back(static_cast<int>(degrees->GetComponent(c, k)));
    }
  }
  return m;
}

/// n-point Gauss-Legendre nodes and weights on [0, 1] (Newton on P_n).
void GaussLegendre(int n, std::vector<double>& x, std::vector<double>& w)
{
  x.resize(n);
  w.resize(n);
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i)
  {
    double z = std::cos(pi * (i + 0.75) / (n + 0.5)), dp = 0.0;
    for (int it = 0; it < 100; ++it)
    {
      double p0 = 1.0, p1 = z;
      for (int k = 2; k <= n; ++k)
      {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1.0);
      const double step = p1 / dp;
      z -= step;
      if (std::abs(step) < 1e-16)
      {
        break;
      }
    }
    x[i] = 0.5 * (1.0 - z);
    w[i] = 1.0 / ((1.0 - z * z) * dp * dp); // (2 / ((1-z^2) P'^2)) / 2 on [0, 1]
  }
}

double Det(const double J[9])
{
  return J[0] * (J[4] * J[8] - J[5] * J[7]) - J[1] * (J[3] * J[8] - J[5] * J[6]) +
    J[2] * (J[3] * J[7] - J[4] * J[6]);
}

/// Volume of every cell by quadrature, and the worst inversion round trip.
void VolumeAndInversion(const MeshArrays& m, double& volume, double& worstRoundTrip, int& failures)
{
  std::vector<double> gx, gw;
  GaussLegendre(8, gx, gw);
  std::map<std::vector<int>, hov::LagrangeBasis> bases;
  std::mt19937_64 rng(7);
  volume = 0.0;
  worstRoundTrip = 0.0;
  failures = 0;
  for (size_t c = 0; c + 1 < m.Offsets.size(); ++c)
  {
    const int n = static_cast<int>(m.Offsets[c + 1] - m.Offsets[c]);
    const int* deg = m.Degrees.empty() ? nullptr : &m.Degrees[3 * c];
    std::vector<int> key{ m.Types[c], n, deg ? deg[0] : 0, deg ? deg[1] : 0, deg ? deg[2] : 0 };
    hov::LagrangeBasis& b = bases[key];
    if (!b.IsInitialized() && !b.Initialize(static_cast<hov::LagrangeShape>(m.Types[c]), n, deg))
    {
      ++failures;
      continue;
    }
    std::vector<double> pts(3 * n);
    for (int i = 0; i < n; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        pts[3 * i + k] = m.Points[3 * m.Connectivity[m.Offsets[c] + i] + k];
      }
    }
    const hov::LagrangeCellView view{ &b, pts.data(), nullptr };
    const bool tet = b.GetShape() == hov::LagrangeShape::Tetra;
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j)
        for (int k = 0; k < 8; ++k)
        {
          const double u = gx[i], v = gx[j], w = gx[k];
          // Tetrahedra: Duffy map (u, (1-u) v, (1-u)(1-v) w), Jacobian (1-u)^2 (1-v).
          const double pc[3] = { u, tet ? (1 - u) * v : v, tet ? (1 - u) * (1 - v) * w : w };
          const double jac = tet ? (1 - u) * (1 - u) * (1 - v) : 1.0;
          double x[3], J[9];
          hov::EvaluateLagrangePosition(view, pc, x, J);
          volume += gw[i] * gw[j] * gw[k] * jac * Det(J);
        }
    for (int trial = 0; trial < 3; ++trial)
    {
      std::uniform_real_distribution<double> uni(0.02, 0.98);
      double pc[3];
      do
      {
        pc[0] = uni(rng);
        pc[1] = uni(rng);
        pc[2] = uni(rng);
      } while (b.DistanceOutside(pc) > -0.02);
      double x[3], found[3] = { 0.25, 0.25, 0.25 };
      hov::EvaluateLagrangePosition(view, pc, x);
      if (!hov::InvertLagrangeGeometry(view, x, found).Converged())
      {
        ++failures;
        continue;
      }
      for (int k = 0; k < 3; ++k)
      {
        worstRoundTrip = std::max(worstRoundTrip, std::abs(found[k] - pc[k]));
      }
    }
  }
}

/// An orthographic W x W image along -z (platehole) or -z through the bounds' centre.
void RayCast(Checker& ck, const MeshArrays& m, const char* name, double lo, double hi, int W)
{
  hov::CurvedRayCaster caster;
  std::string msg;
  const auto buildStart = std::chrono::steady_clock::now();
  ck.Check(caster.Build(m.Input(), &msg) && caster.GetNumberOfSkippedCells() == 0,
    std::string(name) + ": caster built, no skipped cell " + msg);
  std::cout << "[measured] " << name << " caster Build: "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - buildStart).count()
            << " s" << std::endl;
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::VTKUnstructured;
  const double span = hi - lo;
  spec.Color = { { lo, 0.1, 0.2, 0.9 }, { lo + 0.5 * span, 0.2, 0.9, 0.2 }, { hi, 0.9, 0.1, 0.1 } };
  spec.Opacity = { { lo, 0.0 }, { lo + 0.3 * span, 0.2 }, { lo + 0.6 * span, 0.6 }, { hi, 1.0 } };
  spec.UnitDistance = 0.05 * (caster.GetBounds()[1] - caster.GetBounds()[0]);
  hov::TransferFunction tf;
  ck.Check(tf.Build(spec), "table built");
  const double* B = caster.GetBounds();
  bool finite = true;
  double worstError = 0.0, maxAlpha = 0.0;
  int segments = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int j = 0; j < W; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      const double o[3] = { B[0] + (i + 0.5) / W * (B[1] - B[0]), B[2] + (j + 0.5) / W * (B[3] - B[2]),
        B[5] + 1.0 };
      const double d[3] = { 0.0, 0.0, -1.0 };
      double error = 0.0;
      hov::CurvedRayStats stats;
      const hov::RGBA c = caster.TraceRay(o, d, 0.0, B[5] - B[4] + 2.0, tf, {}, &error, &stats);
      finite = finite && std::isfinite(c.R) && std::isfinite(c.A) && c.A >= 0.0 && c.A <= 1.0;
      worstError = std::max(worstError, error);
      maxAlpha = std::max(maxAlpha, c.A);
      segments += stats.Segments;
    }
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "[measured] " << name << " ray casting " << W << "x" << W << ": " << segments
            << " segments, max alpha " << maxAlpha << ", worst error estimate " << worstError
            << ", " << 1e3 * seconds / (W * W) << " ms per ray (single thread, shared machine)"
            << std::endl;
  ck.Check(finite, std::string(name) + ": finite colours, alpha in [0, 1]");
  ck.Check(maxAlpha > 0.01 && segments > 0, std::string(name) + ": something visible");
  ck.Check(worstError < 1e-3, std::string(name) + ": error estimates below 0.001");
}
}

int TestLagrangeDatasets(int argc, char* argv[])
{
  Checker ck;
  const std::string data = ArgAfter(argc, argv, "-D", ".");
  struct Set
  {
    const char* File;
    const char* Array;
    double ReferenceVolume;
    int Cells;
    double Lo, Hi;
    int Pixels;
  };
  const Set sets[2] = { { "platehole_lagrange_hex_q4.vtu", "von_mises", 0.09509126148, 192, 1.8, 361.0, 12 },
    { "tjunction_lagrange_tet_p4.vtu", "speed", 3.65787548, 3790, 0.05, 2.63, 6 } };
  for (const Set& s : sets)
  {
    vtkSmartPointer<vtkUnstructuredGrid> grid = hovTestRef::LoadDataset(data, s.File, s.Array);
    if (!ck.Check(grid->GetNumberOfCells() == s.Cells && grid->GetPointData()->GetScalars(),
          std::string(s.File) + ": loaded"))
    {
      continue;
    }
    const MeshArrays m = Convert(grid);
    double volume = 0.0, roundTrip = 0.0;
    int failures = 0;
    VolumeAndInversion(m, volume, roundTrip, failures);
    const double rel = std::abs(volume - s.ReferenceVolume) / s.ReferenceVolume;
    std::cout << "[measured] " << s.File << ": volume " << volume << " (reference "
              << s.ReferenceVolume << ", relative difference " << rel
              << "), worst inversion round trip " << roundTrip << std::endl;
    // The reference has 10 (9) significant digits.
    ck.Check(rel < 1e-8, "curved volume matches the reference");
    ck.Check(failures == 0 && roundTrip < 1e-11, "every cell initialised and inverted");
    RayCast(ck, m, s.File, s.Lo, s.Hi, s.Pixels);
  }
  return ck.Result();
}
