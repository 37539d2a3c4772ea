/**
 * @file hovLagrangeTestSupport.h
 * @brief Test cells for the TestLagrange* / TestCurved* / TestEnclosure*
 * kernel tests: Lagrange cells of every type and order whose nodes are
 * placed by a smooth map of the reference domain (affine, or affine plus a
 * bending term: curved edges and faces), optionally with random node
 * perturbations, and node scalars from a smooth function.
 */
#ifndef hovLagrangeTestSupport_h
#define hovLagrangeTestSupport_h

#include "hovLagrangeBasis.h"
#include "hovLagrangeCell.h"

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace hovtest
{
/// A Lagrange cell with its own storage; View() binds it.
struct LagrangeTestCell
{
  hov::LagrangeBasis Basis;
  std::vector<double> Points;
  std::vector<double> Scalars;
  hov::LagrangeCellView View() const { return { &this->Basis, this->Points.data(), this->Scalars.data() }; }
};

/// One (shape, orders) case.
struct LagrangeCase
{
  hov::LagrangeShape Shape;
  int Order[3];
  int NodeCount; ///< only for the special cells (15-node tet, 21-node wedge), else 0
  std::string Name() const
  {
    return "type" + std::to_string(static_cast<int>(this->Shape)) + "_p" +
      std::to_string(this->Order[0]) + std::to_string(this->Order[1]) +
      std::to_string(this->Order[2]) + (this->NodeCount ? "_n" + std::to_string(this->NodeCount) : "");
  }
};

/**
 * min det J / max det J over the nodes and 200 random points: > 0 means the
 * map is (very likely) injective; the tests want well-shaped cells (> 0.2).
 */
inline double MinJacobianRatio(const hov::LagrangeCellView& view, std::mt19937_64& rng)
{
  double lo = 1e300, hi = -1e300;
  const int n = view.Basis->GetNodeCount();
  for (int i = 0; i < n + 200; ++i)
  {
    double pc[3], x[3], J[9];
    if (i < n)
    {
      view.Basis->NodeParametricCoords(i, pc);
    }
    else
    {
      std::uniform_real_distribution<double> u(0.0, 1.0);
      do
      {
        pc[0] = u(rng);
        pc[1] = u(rng);
        pc[2] = u(rng);
      } while (view.Basis->DistanceOutside(pc) > 0.0);
    }
    hov::EvaluateLagrangePosition(view, pc, x, J);
    const double det = J[0] * (J[4] * J[8] - J[5] * J[7]) - J[1] * (J[3] * J[8] - J[5] * J[6]) +
      J[2] * (J[3] * J[7] - J[4] * J[6]);
    lo = std::min(lo, det);
    hi = std::max(hi, det);
  }
  return lo / hi;
}

/// Every shape with uniform orders 1..maxOrder, a few anisotropic orders, the special cells.
inline std::vector<LagrangeCase> AllLagrangeCases(int maxOrder)
{
  using S = hov::LagrangeShape;
  std::vector<LagrangeCase> cases;
  for (int p = 1; p <= maxOrder; ++p)
  {
    cases.push_back({ S::Tetra, { p, p, p }, 0 });
    cases.push_back({ S::Hexahedron, { p, p, p }, 0 });
    cases.push_back({ S::Wedge, { p, p, p }, 0 });
  }
  cases.push_back({ S::Hexahedron, { 1, 2, 3 }, 0 });
  cases.push_back({ S::Hexahedron, { 4, 2, 1 }, 0 });
  cases.push_back({ S::Wedge, { 3, 3, 1 }, 0 });
  cases.push_back({ S::Wedge, { 1, 1, 4 }, 0 });
  cases.push_back({ S::Tetra, { 2, 2, 2 }, 15 });
  cases.push_back({ S::Wedge, { 2, 2, 2 }, 21 });
  return cases;
}

/// Initialise @p basis for @p c (the special cells by their node count).
inline bool InitBasis(const LagrangeCase& c, hov::LagrangeBasis& basis)
{
  const int n = c.NodeCount ? c.NodeCount : hov::LagrangeNodeCount(c.Shape, c.Order);
  return basis.Initialize(c.Shape, n, c.NodeCount ? nullptr : c.Order);
}

/// A random parametric point inside the domain, at least @p margin from its boundary.
inline void RandomPC(const hov::LagrangeBasis& b, std::mt19937_64& rng, double margin, double pc[3])
{
  std::uniform_real_distribution<double> u(0.0, 1.0);
  do
  {
    for (int k = 0; k < 3; ++k)
    {
      pc[k] = u(rng);
    }
  } while (b.DistanceOutside(pc) > -margin);
}

/// A ray through @p x in a random direction (unit, from @p n01): d, and the
/// origin o = x - back d.
inline void RandomRayThrough(const double x[3], double back, std::mt19937_64& rng,
  std::normal_distribution<double>& n01, double o[3], double d[3])
{
  double len = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    d[k] = n01(rng);
    len += d[k] * d[k];
  }
  len = std::sqrt(len);
  for (int k = 0; k < 3; ++k)
  {
    d[k] /= len;
    o[k] = x[k] - back * d[k];
  }
}

/// Geometry x = M pc + c + bend * (sin-type bending), the same map for every node.
struct SmoothMap
{
  double M[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double C[3] = { 0, 0, 0 };
  double Bend = 0.0;
  void Apply(const double pc[3], double x[3]) const
  {
    for (int i = 0; i < 3; ++i)
    {
      x[i] = this->C[i] + this->M[3 * i] * pc[0] + this->M[3 * i + 1] * pc[1] +
        this->M[3 * i + 2] * pc[2];
    }
    // Bending: smooth, injective for |Bend| <~ 0.15 on the unit cube.
    x[0] += this->Bend * std::sin(2.0 * pc[1] + pc[2]);
    x[1] += this->Bend * std::cos(1.5 * pc[2] + 0.5 * pc[0]) * pc[0];
    x[2] += this->Bend * (pc[0] * pc[0] - pc[1] * pc[1]);
  }
};

/// M = I + 0.3 U (U uniform in [-1,1]) scaled by @p size, C random in [-1,1].
inline SmoothMap RandomMap(std::mt19937_64& rng, double bend, double size = 1.0)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  SmoothMap m;
  for (int i = 0; i < 9; ++i)
  {
    m.M[i] = size * ((i % 4 == 0 ? 1.0 : 0.0) + 0.3 * u(rng));
  }
  for (double& c : m.C)
  {
    c = u(rng);
  }
  m.Bend = bend * size;
  return m;
}

/**
 * Nodes at map(node pcoords) plus uniform noise of size @p noise on every
 * non-corner node; scalars from @p field at the node positions.
 */
inline void PlaceNodes(LagrangeTestCell& cell,
  const std::function<void(const double*, double*)>& map, double noise, std::mt19937_64& rng,
  const std::function<double(const double*)>& field)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = cell.Basis.GetNodeCount();
  cell.Points.resize(3 * n);
  cell.Scalars.resize(n);
  for (int i = 0; i < n; ++i)
  {
    double pc[3];
    cell.Basis.NodeParametricCoords(i, pc);
    map(pc, &cell.Points[3 * i]);
    const bool corner = i < (cell.Basis.GetShape() == hov::LagrangeShape::Tetra
                                ? 4
                                : cell.Basis.GetShape() == hov::LagrangeShape::Wedge ? 6 : 8);
    for (int k = 0; k < 3 && !corner; ++k)
    {
      cell.Points[3 * i + k] += noise * u(rng);
    }
    cell.Scalars[i] = field(&cell.Points[3 * i]);
  }
}

/// PlaceNodes with a SmoothMap.
inline void PlaceNodes(LagrangeTestCell& cell, const SmoothMap& map, double noise,
  std::mt19937_64& rng, const std::function<double(const double*)>& field)
{
  PlaceNodes(
    cell, [&map](const double* pc, double* x) { map.Apply(pc, x); }, noise, rng, field);
}
}

#endif
