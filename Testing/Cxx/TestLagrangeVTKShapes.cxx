// Cross-check of the Lagrange kernels (hovLagrangeBasis.h, hovLagrangeCell.h)
// against VTK 9.1's own classes, for tetrahedra, hexahedra and wedges of
// orders 1..8 (plus anisotropic orders and the 15-node tetrahedron and
// 21-node wedge):
//  - node numbering: our node table against vtkHigherOrderHexahedron /
//    vtkHigherOrderWedge::PointIndexFromIJK and vtkHigherOrderTetra::Index;
//  - node parametric coordinates against GetParametricCoords();
//  - shape functions against vtkLagrange*::InterpolateFunctions and the
//    static vtkLagrangeInterpolation::Tensor3ShapeFunctions /
//    WedgeShapeFunctions; derivatives against InterpolateDerivs (note: VTK
//    9.1's Lagrange HEXAHEDRON returns them interleaved per node,
//    derivs[3 i + d], unlike the tetrahedron and wedge, derivs[d n + i]);
//  - informational: VTK's EvaluatePosition round-trip error on a curved
//    cubic hexahedron against our Newton inversion.
#include "hovLagrangeBasis.h"
#include "hovLagrangeCell.h"

#include "vtkHigherOrderHexahedron.h"
#include "vtkHigherOrderTetra.h"
#include "vtkHigherOrderWedge.h"
#include "vtkLagrangeHexahedron.h"
#include "vtkLagrangeInterpolation.h"
#include "vtkLagrangeTetra.h"
#include "vtkLagrangeWedge.h"
#include "vtkNew.h"
#include "vtkPoints.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
using hov::LagrangeShape;

struct Case
{
  LagrangeShape Shape;
  int Order[3];
  int Nodes; // 0: from the orders
};

std::string Name(const Case& c)
{
  return "type " + std::to_string(static_cast<int>(c.Shape)) + " orders " +
    std::to_string(c.Order[0]) + "," + std::to_string(c.Order[1]) + "," +
    std::to_string(c.Order[2]) + " nodes " + std::to_string(c.Nodes);
}

/// The VTK cell of the case, with node positions = parametric coordinates + a bend.
vtkCell* MakeVTKCell(const Case& c, const hov::LagrangeBasis& b, vtkNew<vtkLagrangeTetra>& tet,
  vtkNew<vtkLagrangeHexahedron>& hex, vtkNew<vtkLagrangeWedge>& wedge, std::vector<double>& pts)
{
  const int n = b.GetNodeCount();
  vtkCell* cell = c.Shape == LagrangeShape::Tetra
    ? static_cast<vtkCell*>(tet.GetPointer())
    : c.Shape == LagrangeShape::Hexahedron ? static_cast<vtkCell*>(hex.GetPointer())
                                           : static_cast<vtkCell*>(wedge.GetPointer());
  cell->GetPoints()->SetNumberOfPoints(n);
  cell->GetPointIds()->SetNumberOfIds(n);
  pts.resize(3 * n);
  for (int i = 0; i < n; ++i)
  {
    double pc[3];
    b.NodeParametricCoords(i, pc);
    pts[3 * i] = pc[0] + 0.1 * std::sin(2 * pc[1]);
    pts[3 * i + 1] = pc[1] + 0.1 * pc[0] * pc[2];
    pts[3 * i + 2] = pc[2] + 0.08 * (pc[0] * pc[0] - pc[1]);
    cell->GetPoints()->SetPoint(i, &pts[3 * i]);
    cell->GetPointIds()->SetId(i, i);
  }
  if (c.Shape == LagrangeShape::Hexahedron)
  {
    hex->SetOrder(c.Order[0], c.Order[1], c.Order[2]);
  }
  else if (c.Shape == LagrangeShape::Wedge)
  {
    wedge->SetOrder(c.Order[0], c.Order[1], c.Order[2], n);
  }
  cell->Initialize();
  return cell;
}

/// Node numbering against VTK's static index functions; returns failures.
int CheckNumbering(const Case& c, const hov::LagrangeBasis& b)
{
  if (b.IsSpecial())
  {
    return 0;
  }
  int failures = 0;
  const int order[4] = { c.Order[0], c.Order[1], c.Order[2], b.GetNodeCount() };
  for (int node = 0; node < b.GetNodeCount(); ++node)
  {
    const std::array<int, 4>& idx = b.NodeIndex(node);
    int vtkIndex = -1;
    if (c.Shape == LagrangeShape::Hexahedron)
    {
      vtkIndex = vtkHigherOrderHexahedron::PointIndexFromIJK(idx[0], idx[1], idx[2], order);
    }
    else if (c.Shape == LagrangeShape::Wedge)
    {
      vtkIndex = vtkHigherOrderWedge::PointIndexFromIJK(idx[0], idx[1], idx[2], order);
    }
    else
    {
      const vtkIdType bindex[4] = { idx[0], idx[1], idx[2], idx[3] };
      vtkIndex = static_cast<int>(vtkHigherOrderTetra::Index(bindex, c.Order[0]));
    }
    if (vtkIndex != node)
    {
      std::cerr << "ERROR: numbering " << Name(c) << " node " << node << " VTK " << vtkIndex
                << "\n";
      ++failures;
    }
  }
  return failures;
}

/// Shape functions and derivatives at random points; returns the worst relative difference.
double CompareFunctions(const Case& c, const hov::LagrangeBasis& b, vtkCell* cell,
  std::mt19937_64& rng)
{
  const int n = b.GetNodeCount();
  std::vector<double> w(n), wv(n), ws(n), d(3 * n), dv(3 * n);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0.0;
  int order4[4] = { c.Order[0], c.Order[1], c.Order[2], n };
  for (int trial = 0; trial < 10; ++trial)
  {
    double pc[3];
    do
    {
      pc[0] = u(rng);
      pc[1] = u(rng);
      pc[2] = u(rng);
    } while (b.DistanceOutside(pc) > 0.0);
    b.FunctionsAndDerivatives(pc, w.data(), d.data());
    cell->InterpolateFunctions(pc, wv.data());
    cell->InterpolateDerivs(pc, dv.data());
    const bool hex = c.Shape == LagrangeShape::Hexahedron;
    if (hex)
    {
      vtkLagrangeInterpolation::Tensor3ShapeFunctions(c.Order, pc, ws.data());
    }
    else if (c.Shape == LagrangeShape::Wedge)
    {
      vtkLagrangeInterpolation::WedgeShapeFunctions(order4, n, pc, ws.data());
    }
    else
    {
      ws = wv;
    }
    double scaleW = 1.0, scaleD = 1.0;
    for (int i = 0; i < n; ++i)
    {
      scaleW = std::max(scaleW, std::abs(w[i]));
      for (int k = 0; k < 3; ++k)
      {
        scaleD = std::max(scaleD, std::abs(d[k * n + i]));
      }
    }
    for (int i = 0; i < n; ++i)
    {
      worst = std::max(worst, std::abs(w[i] - wv[i]) / scaleW);
      worst = std::max(worst, std::abs(w[i] - ws[i]) / scaleW);
      for (int k = 0; k < 3; ++k)
      {
        const double vtkD = hex ? dv[3 * i + k] : dv[k * n + i];
        worst = std::max(worst, std::abs(d[k * n + i] - vtkD) / scaleD);
      }
    }
  }
  return worst;
}

/// Node parametric coordinates against VTK's; returns the worst difference.
double CompareNodeCoords(const hov::LagrangeBasis& b, vtkCell* cell)
{
  const double* vtkPC = cell->GetParametricCoords();
  double worst = 0.0;
  for (int i = 0; i < b.GetNodeCount(); ++i)
  {
    double pc[3];
    b.NodeParametricCoords(i, pc);
    for (int k = 0; k < 3; ++k)
    {
      worst = std::max(worst, std::abs(pc[k] - vtkPC[3 * i + k]));
    }
  }
  return worst;
}

/// Informational: VTK's EvaluatePosition vs our inversion on a curved cubic hexahedron.
void ReportEvaluatePosition(std::mt19937_64& rng)
{
  Case c{ LagrangeShape::Hexahedron, { 3, 3, 3 }, 0 };
  hov::LagrangeBasis b;
  b.Initialize(c.Shape, 64, c.Order);
  vtkNew<vtkLagrangeTetra> tet;
  vtkNew<vtkLagrangeHexahedron> hex;
  vtkNew<vtkLagrangeWedge> wedge;
  std::vector<double> pts;
  vtkCell* cell = MakeVTKCell(c, b, tet, hex, wedge, pts);
  const hov::LagrangeCellView view{ &b, pts.data(), nullptr };
  std::uniform_real_distribution<double> u(0.05, 0.95);
  double worstVTK = 0.0, worstOurs = 0.0;
  std::vector<double> weights(64);
  for (int trial = 0; trial < 50; ++trial)
  {
    double pc[3] = { u(rng), u(rng), u(rng) }, x[3], vtkPC[3], closest[3], dist2, ours[3];
    hov::EvaluateLagrangePosition(view, pc, x);
    int subId = 0;
    cell->EvaluatePosition(x, closest, subId, vtkPC, dist2, weights.data());
    std::copy(pc, pc + 3, ours);
    ours[0] = 0.5; // a poor guess
    hov::InvertLagrangeGeometry(view, x, ours);
    for (int k = 0; k < 3; ++k)
    {
      worstVTK = std::max(worstVTK, std::abs(vtkPC[k] - pc[k]));
      worstOurs = std::max(worstOurs, std::abs(ours[k] - pc[k]));
    }
  }
  std::cout << "[measured] curved cubic hexahedron round trip x(pc) -> pc: VTK EvaluatePosition "
            << worstVTK << ", hov InvertLagrangeGeometry " << worstOurs << std::endl;
}
}

int TestLagrangeVTKShapes(int, char*[])
{
  std::vector<Case> cases;
  for (int p = 1; p <= 8; ++p)
  {
    cases.push_back({ LagrangeShape::Tetra, { p, p, p }, 0 });
    cases.push_back({ LagrangeShape::Hexahedron, { p, p, p }, 0 });
    cases.push_back({ LagrangeShape::Wedge, { p, p, p }, 0 });
  }
  cases.push_back({ LagrangeShape::Hexahedron, { 1, 2, 3 }, 0 });
  cases.push_back({ LagrangeShape::Hexahedron, { 4, 2, 5 }, 0 });
  cases.push_back({ LagrangeShape::Wedge, { 3, 3, 1 }, 0 });
  cases.push_back({ LagrangeShape::Wedge, { 2, 2, 5 }, 0 });
  cases.push_back({ LagrangeShape::Tetra, { 2, 2, 2 }, 15 });
  cases.push_back({ LagrangeShape::Wedge, { 2, 2, 2 }, 21 });

  std::mt19937_64 rng(2026);
  int failures = 0;
  double worstFunctions = 0.0, worstCoords = 0.0;
  for (const Case& c : cases)
  {
    hov::LagrangeBasis b;
    std::string msg;
    const int n = c.Nodes ? c.Nodes : hov::LagrangeNodeCount(c.Shape, c.Order);
    if (!b.Initialize(c.Shape, n, c.Nodes ? nullptr : c.Order, &msg))
    {
      std::cerr << "ERROR: " << Name(c) << ": " << msg << "\n";
      ++failures;
      continue;
    }
    vtkNew<vtkLagrangeTetra> tet;
    vtkNew<vtkLagrangeHexahedron> hex;
    vtkNew<vtkLagrangeWedge> wedge;
    std::vector<double> pts;
    vtkCell* cell = MakeVTKCell(c, b, tet, hex, wedge, pts);
    failures += CheckNumbering(c, b);
    const double f = CompareFunctions(c, b, cell, rng);
    const double pcErr = CompareNodeCoords(b, cell);
    worstFunctions = std::max(worstFunctions, f);
    worstCoords = std::max(worstCoords, pcErr);
    // Same formulas in the same precision: differences are rounding only.
    if (!(f <= 1e-12) || !(pcErr <= 1e-15))
    {
      std::cerr << "ERROR: " << Name(c) << ": shape functions/derivatives differ by " << f
                << ", node coordinates by " << pcErr << "\n";
      ++failures;
    }
  }
  std::cout << "[measured] Lagrange shape functions and derivatives vs VTK 9.1: worst relative "
               "difference "
            << worstFunctions << ", node coordinates " << worstCoords << " (" << cases.size()
            << " cases)" << std::endl;
  ReportEvaluatePosition(rng);
  return failures == 0 ? 0 : 1;
}
