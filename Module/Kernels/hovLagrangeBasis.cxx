// Lagrange tetrahedra, hexahedra and wedges: see hovLagrangeBasis.h.
#include "hovLagrangeBasis.h"

#include "hovLagrangeFactors.h"   // Lagrange1D, Eta1D
#include "hovLagrangeNumbering.h" // VTK node numbering
#include "hovLagrangeSpecial.h"   // 15-node tetrahedron, 21-node wedge

#include <algorithm> // std::max, std::min
#include <cmath>     // std::round, std::cbrt

namespace hov
{
using detail::Eta1D;
using detail::Lagrange1D;

int LagrangeNodeCount(LagrangeShape shape, const int order[3])
{
  for (int d = 0; d < 3; ++d)
  {
    if (order[d] < 1 || order[d] > MaxLagrangeOrder)
    {
      return 0;
    }
  }
  switch (shape)
  {
    case LagrangeShape::Tetra:
      return (order[0] + 1) * (order[0] + 2) * (order[0] + 3) / 6;
    case LagrangeShape::Hexahedron:
      return (order[0] + 1) * (order[1] + 1) * (order[2] + 1);
    case LagrangeShape::Wedge:
      return order[0] == order[1] ? (order[0] + 1) * (order[0] + 2) / 2 * (order[2] + 1) : 0;
  }
  return 0;
}

bool LagrangeBasis::Initialize(
  LagrangeShape shape, int nodeCount, const int* degrees, std::string* message)
{
  this->NodeCount = 0;
  this->Nodes.clear();
  this->SumNodes.clear();
  this->Special = false;
  this->Shape = shape;
  auto fail = [&](const std::string& why) {
    if (message)
    {
      *message = why;
    }
    this->NodeCount = 0;
    this->Nodes.clear();
    this->SumNodes.clear();
    return false;
  };
  const int type = static_cast<int>(shape);
  if (type < 71 || type > 73)
  {
    return fail("cell type " + std::to_string(type) + " is not a Lagrange tetra/hexahedron/wedge");
  }
  int order[3] = { 0, 0, 0 };
  if ((shape == LagrangeShape::Tetra && nodeCount == detail::Tetra15Nodes) ||
    (shape == LagrangeShape::Wedge && nodeCount == detail::Wedge21Nodes &&
      (!degrees || (degrees[0] == 2 && degrees[1] == 2 && degrees[2] == 2))))
  {
    this->Special = true;
    this->Order[0] = this->Order[1] = this->Order[2] = 2;
    this->NodeCount = nodeCount;
    return true;
  }
  if (degrees && shape != LagrangeShape::Tetra)
  {
    std::copy(degrees, degrees + 3, order);
  }
  else
  {
    // VTK's rule: the uniform order whose node count matches.
    for (int n = 1; n <= MaxLagrangeOrder; ++n)
    {
      const int uniform[3] = { n, n, n };
      if (LagrangeNodeCount(shape, uniform) == nodeCount)
      {
        order[0] = order[1] = order[2] = n;
      }
    }
  }
  if (shape == LagrangeShape::Wedge && order[0] != order[1])
  {
    return fail("wedge degrees (" + std::to_string(order[0]) + ", " + std::to_string(order[1]) +
      ") differ in the triangle's two directions");
  }
  if (LagrangeNodeCount(shape, order) == 0 || LagrangeNodeCount(shape, order) != nodeCount)
  {
    return fail("no Lagrange cell of type " + std::to_string(type) + " with order <= " +
      std::to_string(MaxLagrangeOrder) + " has " + std::to_string(nodeCount) + " nodes" +
      (degrees ? " and degrees (" + std::to_string(degrees[0]) + ", " +
            std::to_string(degrees[1]) + ", " + std::to_string(degrees[2]) + ")"
               : std::string()));
  }
  std::copy(order, order + 3, this->Order);
  this->Nodes.assign(nodeCount, { -1, -1, -1, -1 });
  int filled = 0;
  auto put = [&](int index, int a, int b, int c, int d) {
    if (index >= 0 && index < nodeCount && this->Nodes[index][0] < 0)
    {
      this->Nodes[index] = { a, b, c, d };
      ++filled;
    }
  };
  if (shape == LagrangeShape::Hexahedron)
  {
    for (int k = 0; k <= order[2]; ++k)
      for (int j = 0; j <= order[1]; ++j)
        for (int i = 0; i <= order[0]; ++i)
        {
          const int index = detail::LagrangeHexIndex(i, j, k, order);
          put(index, i, j, k, 0);
          this->SumNodes.push_back(index);
        }
  }
  else if (shape == LagrangeShape::Wedge)
  {
    for (int k = 0; k <= order[2]; ++k)
      for (int j = 0; j <= order[0]; ++j)
        for (int i = 0; i + j <= order[0]; ++i)
        {
          const int index = detail::LagrangeWedgeIndex(i, j, k, order);
          put(index, i, j, k, 0);
          this->SumNodes.push_back(index);
        }
  }
  else
  {
    const int n = order[0];
    for (int a = 0; a <= n; ++a)
      for (int b = 0; a + b <= n; ++b)
        for (int c = 0; a + b + c <= n; ++c)
        {
          const int lambda[4] = { a, b, c, n - a - b - c };
          const int index = detail::LagrangeTetraIndex(lambda, n);
          put(index, a, b, c, n - a - b - c);
          this->SumNodes.push_back(index);
        }
  }
  if (filled != nodeCount)
  {
    return fail("internal error: VTK node numbering did not cover every node");
  }
  this->NodeCount = nodeCount;
  return true;
}

int LagrangeBasis::GetLineDegree() const
{
  if (this->Special)
  {
    return this->Shape == LagrangeShape::Tetra ? 4 : 5; // urst; (t^2)(r s (1-r-s))
  }
  switch (this->Shape)
  {
    case LagrangeShape::Tetra:
      return this->Order[0];
    case LagrangeShape::Wedge:
      return this->Order[0] + this->Order[2];
    default:
      return this->Order[0] + this->Order[1] + this->Order[2];
  }
}

void LagrangeBasis::NodeParametricCoords(int node, double pc[3]) const
{
  if (this->Special)
  {
    (this->Shape == LagrangeShape::Tetra ? detail::Tetra15NodeCoords
                                         : detail::Wedge21NodeCoords)(node, pc);
    return;
  }
  const std::array<int, 4>& n = this->Nodes[node];
  const bool tet = this->Shape == LagrangeShape::Tetra;
  for (int d = 0; d < 3; ++d)
  {
    const int order = tet ? this->Order[0] : (this->Shape == LagrangeShape::Wedge && d < 2)
        ? this->Order[0]
        : this->Order[d];
    pc[d] = static_cast<double>(n[d]) / order;
  }
}

void LagrangeBasis::ParametricCenter(double pc[3]) const
{
  switch (this->Shape)
  {
    case LagrangeShape::Tetra:
      pc[0] = pc[1] = pc[2] = 0.25;
      return;
    case LagrangeShape::Wedge:
      pc[0] = pc[1] = 1.0 / 3.0;
      pc[2] = 0.5;
      return;
    default:
      pc[0] = pc[1] = pc[2] = 0.5;
  }
}

double LagrangeBasis::DistanceOutside(const double pc[3]) const
{
  const double r = pc[0], s = pc[1], t = pc[2];
  switch (this->Shape)
  {
    case LagrangeShape::Tetra:
      return std::max(std::max(-r, -s), std::max(-t, r + s + t - 1.0));
    case LagrangeShape::Wedge:
      return std::max(std::max(std::max(-r, -s), r + s - 1.0), std::max(-t, t - 1.0));
    default:
      return std::max(std::max(std::max(-r, r - 1.0), std::max(-s, s - 1.0)),
        std::max(-t, t - 1.0));
  }
}

template <class Visitor>
void LagrangeBasis::VisitSpecial(const double pc[3], Visitor&& visit) const
{
  double w[detail::Wedge21Nodes], d[3 * detail::Wedge21Nodes];
  const int n = this->NodeCount;
  (this->Shape == LagrangeShape::Tetra ? detail::Tetra15Functions : detail::Wedge21Functions)(
    pc, w, d);
  for (int i = 0; i < n; ++i)
  {
    const double dw[3] = { d[i], d[n + i], d[2 * n + i] };
    visit(i, w[i], dw);
  }
}

template <class Visitor>
void LagrangeBasis::VisitNodes(const double pc[3], bool derivatives, Visitor&& visit) const
{
  if (this->Special)
  {
    this->VisitSpecial(pc, visit);
    return;
  }
  const int n = this->NodeCount;
  double dw[3] = { 0.0, 0.0, 0.0 };
  if (this->Shape == LagrangeShape::Hexahedron)
  {
    Lagrange1D l[3];
    for (int d = 0; d < 3; ++d)
    {
      l[d].Compute(this->Order[d], pc[d], derivatives);
    }
    for (int i = 0; i < n; ++i)
    {
      const std::array<int, 4>& ijk = this->Nodes[i];
      const double a = l[0].L[ijk[0]], b = l[1].L[ijk[1]], c = l[2].L[ijk[2]];
      if (derivatives)
      {
        dw[0] = l[0].D[ijk[0]] * b * c;
        dw[1] = a * l[1].D[ijk[1]] * c;
        dw[2] = a * b * l[2].D[ijk[2]];
      }
      visit(i, a * b * c, dw);
    }
  }
  else if (this->Shape == LagrangeShape::Wedge)
  {
    const int p = this->Order[0];
    Eta1D e[3];
    e[0].Compute(p, pc[0]);
    e[1].Compute(p, pc[1]);
    e[2].Compute(p, 1.0 - pc[0] - pc[1]);
    Lagrange1D l;
    l.Compute(this->Order[2], pc[2], derivatives);
    for (int i = 0; i < n; ++i)
    {
      const std::array<int, 4>& ijk = this->Nodes[i];
      const int c = p - ijk[0] - ijk[1];
      const double a0 = e[0].E[ijk[0]], a1 = e[1].E[ijk[1]], a2 = e[2].E[c];
      const double tri = a0 * a1 * a2, lt = l.L[ijk[2]];
      if (derivatives)
      {
        dw[0] = (e[0].D[ijk[0]] * a1 * a2 - a0 * a1 * e[2].D[c]) * lt;
        dw[1] = (a0 * e[1].D[ijk[1]] * a2 - a0 * a1 * e[2].D[c]) * lt;
        dw[2] = tri * l.D[ijk[2]];
      }
      visit(i, tri * lt, dw);
    }
  }
  else
  {
    const int p = this->Order[0];
    Eta1D e[4];
    for (int d = 0; d < 3; ++d)
    {
      e[d].Compute(p, pc[d]);
    }
    e[3].Compute(p, 1.0 - pc[0] - pc[1] - pc[2]);
    for (int i = 0; i < n; ++i)
    {
      const std::array<int, 4>& lam = this->Nodes[i];
      const double a = e[0].E[lam[0]], b = e[1].E[lam[1]], c = e[2].E[lam[2]],
                   u = e[3].E[lam[3]];
      if (derivatives)
      {
        const double du = a * b * c * e[3].D[lam[3]];
        dw[0] = e[0].D[lam[0]] * b * c * u - du;
        dw[1] = a * e[1].D[lam[1]] * c * u - du;
        dw[2] = a * b * e[2].D[lam[2]] * u - du;
      }
      visit(i, a * b * c * u, dw);
    }
  }
}

void LagrangeBasis::Functions(const double pc[3], double* w) const
{
  this->VisitNodes(pc, false, [w](int i, double wi, const double*) { w[i] = wi; });
}

void LagrangeBasis::FunctionsAndDerivatives(const double pc[3], double* w, double* derivs) const
{
  const int n = this->NodeCount;
  this->VisitNodes(pc, true, [=](int i, double wi, const double* dw) {
    if (w)
    {
      w[i] = wi;
    }
    derivs[i] = dw[0];
    derivs[n + i] = dw[1];
    derivs[2 * n + i] = dw[2];
  });
}

template <int C, bool G>
void LagrangeBasis::InterpolateNodes(
  const double pc[3], const double* values, double* value, double* gradient) const
{
  double v[C] = {}, g[3 * C] = {};
  this->VisitNodes(pc, G, [&](int i, double wi, const double* dw) {
    const double* node = values + static_cast<size_t>(i) * C;
    for (int c = 0; c < C; ++c)
    {
      v[c] += wi * node[c];
      if (G)
      {
        g[3 * c] += dw[0] * node[c];
        g[3 * c + 1] += dw[1] * node[c];
        g[3 * c + 2] += dw[2] * node[c];
      }
    }
  });
  std::copy(v, v + C, value);
  if (G)
  {
    std::copy(g, g + 3 * C, gradient);
  }
}

void LagrangeBasis::Interpolate(const double pc[3], const double* values, int components,
  double* value, double* gradient) const
{
  components = std::min(std::max(components, 1), 4);
  if (!this->Special)
  {
    this->InterpolateFactorised(pc, values, components, value, gradient);
    return;
  }
  // The special cells, with compile-time loops for positions (3) and scalars (1).
  if (components == 3 || components == 1)
  {
    const bool three = components == 3;
    if (gradient)
    {
      three ? this->InterpolateNodes<3, true>(pc, values, value, gradient)
            : this->InterpolateNodes<1, true>(pc, values, value, gradient);
    }
    else
    {
      three ? this->InterpolateNodes<3, false>(pc, values, value, gradient)
            : this->InterpolateNodes<1, false>(pc, values, value, gradient);
    }
    return;
  }
  double v[4] = { 0.0, 0.0, 0.0, 0.0 }, g[12] = {};
  this->VisitNodes(pc, gradient != nullptr, [&](int i, double wi, const double* dw) {
    const double* node = values + static_cast<size_t>(i) * components;
    for (int c = 0; c < components; ++c)
    {
      v[c] += wi * node[c];
      g[3 * c] += dw[0] * node[c];
      g[3 * c + 1] += dw[1] * node[c];
      g[3 * c + 2] += dw[2] * node[c];
    }
  });
  std::copy(v, v + components, value);
  if (gradient)
  {
    std::copy(g, g + 3 * components, gradient);
  }
}
}
