// Grid -> Lagrange mesh of the ray caster: see hov::RayCastCells.h.
#include "hovRayCastCells.h"

#include "hovLagrangeBasis.h" // node parametric coordinates, Jacobians

#include "vtkCellData.h"
#include "vtkPointData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkGenericCell.h" // the source cell's shape functions
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm> // std::max
#include <cmath>     // std::isfinite
#include <map>       // basis cache
#include <tuple>     // basis cache key
#include <utility>   // std::move

namespace
{
/// Lagrange type and order a linear/quadratic VTK cell is converted to (false: not handled).
bool ConversionTarget(int type, int& lagrangeType, int& order)
{
  switch (type)
  {
    case VTK_TETRA: lagrangeType = 71; order = 1; return true;
    case VTK_VOXEL:
    case VTK_HEXAHEDRON: lagrangeType = 72; order = 1; return true;
    case VTK_WEDGE: lagrangeType = 73; order = 1; return true;
    // vtkPyramid's interpolant is the trilinear hexahedron's with the top face
    // collapsed to the apex (N0..N3 = (1-r)(1-s)(1-t) ..., N4 = t), and every
    // vtkQuadraticPyramid function is of degree <= 2 in each of r, s, t: an
    // order-1 (order-2) hexahedron whose top nodes sit at the apex carries the
    // same map and field, node values from the pyramid's own interpolation.
    case VTK_PYRAMID: lagrangeType = 72; order = 1; return true;
    case VTK_QUADRATIC_PYRAMID: lagrangeType = 72; order = 2; return true;
    case VTK_QUADRATIC_TETRA: lagrangeType = 71; order = 2; return true;
    case VTK_QUADRATIC_HEXAHEDRON:
    case VTK_TRIQUADRATIC_HEXAHEDRON: lagrangeType = 72; order = 2; return true;
    case VTK_QUADRATIC_WEDGE:
    case VTK_BIQUADRATIC_QUADRATIC_WEDGE: lagrangeType = 73; order = 2; return true;
    default: return false;
  }
}

/// Largest node count whose derivative table BasisEntry keeps (3 n (n + 1)
/// doubles: 2.9 MB at 343 nodes, an order-6 hexahedron); larger bases compute
/// the derivatives per cell, as before.
constexpr int MaxTabulatedNodes = 343;

/// A basis and the derivatives of its functions at its nodes and centre
/// (CheckJacobian's points, the same for every cell of the basis: computed
/// once per basis instead of once per cell).
struct BasisEntry
{
  hov::LagrangeBasis Basis;
  /// Block k (k <= n, k = n the centre) of 3 n values: dN_i / dpc_d at 3 k n + d n + i.
  std::vector<double> NodeDerivatives;

  void Prepare()
  {
    const int n = this->Basis.IsInitialized() ? this->Basis.GetNodeCount() : 0;
    if (n > MaxTabulatedNodes)
    {
      return;
    }
    this->NodeDerivatives.assign(3 * static_cast<size_t>(n) * (n + 1), 0.0);
    for (int k = 0; k < n + 1 && n > 0; ++k)
    {
      double pc[3];
      k < n ? this->Basis.NodeParametricCoords(k, pc) : this->Basis.ParametricCenter(pc);
      this->Basis.FunctionsAndDerivatives(
        pc, nullptr, &this->NodeDerivatives[3 * static_cast<size_t>(k) * n]);
    }
  }
};

/**
 * det J at every node and the centre: 1 all of the expected sign (wedges:
 * either uniform sign, VTK's wedge orientation convention varies between
 * writers), 0 degenerate or tangled (|det| <= 1e-12 size^3 or mixed signs),
 * -1 uniformly inverted (tetrahedra, hexahedra).
 */
int CheckJacobian(const BasisEntry& entry, const double* x, bool collapsedTop = false)
{
  const hov::LagrangeBasis& basis = entry.Basis;
  const int n = basis.GetNodeCount();
  double lo[3] = { x[0], x[1], x[2] }, hi[3] = { x[0], x[1], x[2] };
  for (int i = 1; i < n; ++i)
  {
    for (int r = 0; r < 3; ++r)
    {
      lo[r] = std::min(lo[r], x[3 * i + r]);
      hi[r] = std::max(hi[r], x[3 * i + r]);
    }
  }
  const double size = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
  const double floor = 1e-12 * size * size * size;
  int positive = 0, negative = 0;
  const bool tabulated = !entry.NodeDerivatives.empty();
  std::vector<double> local(tabulated ? 0 : 3 * static_cast<size_t>(n));
  for (int k = 0; k <= n; ++k)
  {
    double pc[3];
    k < n ? basis.NodeParametricCoords(k, pc) : basis.ParametricCenter(pc);
    if (collapsedTop && pc[2] == 1.0)
    {
      continue; // a pyramid's apex (the collapsed top face): the Jacobian vanishes there
    }
    if (!tabulated)
    {
      basis.FunctionsAndDerivatives(pc, nullptr, local.data());
    }
    const double* derivs =
      tabulated ? &entry.NodeDerivatives[3 * static_cast<size_t>(k) * n] : local.data();
    double j[9] = { 0, 0, 0, 0, 0, 0, 0, 0, 0 }; // j[3 r + d] = dx_r / dpc_d
    for (int i = 0; i < n; ++i)
    {
      for (int d = 0; d < 3; ++d)
      {
        const double w = derivs[static_cast<size_t>(d) * n + i];
        for (int r = 0; r < 3; ++r)
        {
          j[3 * r + d] += w * x[3 * i + r];
        }
      }
    }
    const double det = j[0] * (j[4] * j[8] - j[5] * j[7]) - j[1] * (j[3] * j[8] - j[5] * j[6]) +
      j[2] * (j[3] * j[7] - j[4] * j[6]);
    if (!(std::fabs(det) > floor))
    {
      return 0;
    }
    (det > 0.0 ? positive : negative)++;
  }
  if (positive && negative)
  {
    return 0;
  }
  return (negative && basis.GetShape() != hov::LagrangeShape::Wedge) ? -1 : 1;
}

/// True if a point of the cell has a rational weight other than 1.
bool IsRational(vtkDataArray* weights, const vtkIdType* ids, vtkIdType n)
{
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (ids[i] < 0 || ids[i] >= weights->GetNumberOfTuples() ||
      weights->GetComponent(ids[i], 0) != 1.0)
    {
      return true;
    }
  }
  return false;
}

double PointValue(vtkDataArray* scalars, vtkIdType i, int component)
{
  const int nc = scalars->GetNumberOfComponents();
  if (component >= 0 || nc == 1)
  {
    return scalars->GetComponent(i, std::max(component, 0));
  }
  double sum = 0.0;
  for (int c = 0; c < nc; ++c)
  {
    const double v = scalars->GetComponent(i, c);
    sum += v * v;
  }
  return std::sqrt(sum);
}
}

vtkIdType hov::RayCastCells::Convert(
  vtkUnstructuredGrid* grid, vtkDataArray* scalars, int component, bool cellScalars)
{
  *this = hov::RayCastCells();
  this->Offsets.push_back(0);
  const vtkIdType np = grid->GetNumberOfPoints();
  this->Cells = grid->GetNumberOfCells();
  this->Points.resize(3 * static_cast<size_t>(np));
  this->Scalars.resize(static_cast<size_t>(np));
  for (vtkIdType i = 0; i < np; ++i)
  {
    grid->GetPoints()->GetPoint(i, &this->Points[3 * static_cast<size_t>(i)]);
    this->Scalars[i] = cellScalars ? 0.0 : PointValue(scalars, i, component);
  }
  vtkDataArray* degreesArray = grid->GetCellData()->GetHigherOrderDegrees();
  vtkDataArray* weights = grid->GetPointData()->GetRationalWeights();
  const bool useDegrees = degreesArray && degreesArray->GetNumberOfComponents() == 3 &&
    degreesArray->GetNumberOfTuples() == this->Cells;
  std::map<std::tuple<int, int, int, int, int>, BasisEntry> bases;
  vtkNew<vtkGenericCell> source;
  std::vector<double> x, s, w;
  for (vtkIdType c = 0; c < this->Cells; ++c)
  {
    const int type = grid->GetCellType(c);
    vtkIdType n;
    const vtkIdType* ids;
    grid->GetCellPoints(c, n, ids);
    int lagrangeType = type, order = 0, deg[3] = { 0, 0, 0 };
    const bool native = type >= 71 && type <= 73;
    // Bezier tetrahedra, hexahedra and wedges (78-80): the Lagrange cell of the same
    // type and order through the same polynomial (its values at the Lagrange nodes).
    const bool bezier = type >= VTK_BEZIER_TETRAHEDRON && type <= VTK_BEZIER_WEDGE;
    if (bezier)
    {
      lagrangeType = type - (VTK_BEZIER_TETRAHEDRON - VTK_LAGRANGE_TETRAHEDRON);
    }
    else if (!native && !ConversionTarget(type, lagrangeType, order))
    {
      this->FirstUnsupportedType = this->Unsupported++ ? this->FirstUnsupportedType : type;
      continue;
    }
    if (bezier && weights && IsRational(weights, ids, n))
    {
      ++this->Rational; // not a polynomial: no Lagrange cell represents it
      continue;
    }
    if ((native || bezier) && useDegrees)
    {
      for (int k = 0; k < 3; ++k)
      {
        deg[k] = static_cast<int>(degreesArray->GetComponent(c, k));
      }
    }
    else if (!native)
    {
      deg[0] = deg[1] = deg[2] = order;
    }
    const int nodes = (native || bezier)
      ? static_cast<int>(n)
      : hov::LagrangeNodeCount(static_cast<hov::LagrangeShape>(lagrangeType), deg);
    const auto key = std::make_tuple(lagrangeType, nodes, deg[0], deg[1], deg[2]);
    auto it = bases.find(key);
    if (it == bases.end())
    {
      BasisEntry entry;
      if (!entry.Basis.Initialize(static_cast<hov::LagrangeShape>(lagrangeType), nodes,
            ((native || bezier) && !useDegrees) ? nullptr : deg))
      {
        entry.Basis = hov::LagrangeBasis();
      }
      entry.Prepare();
      it = bases.emplace(key, std::move(entry)).first;
    }
    const hov::LagrangeBasis& basis = it->second.Basis;
    // Cell scalars: the cell's value at each of its own (copied) nodes.
    const double cellValue = cellScalars ? PointValue(scalars, c, component) : 0.0;
    bool ok = basis.IsInitialized() && std::isfinite(cellValue);
    for (vtkIdType i = 0; i < n && ok; ++i)
    {
      ok = ids[i] >= 0 && ids[i] < np && std::isfinite(this->Scalars[ids[i]]);
      for (int r = 0; r < 3 && ok; ++r)
      {
        ok = std::isfinite(this->Points[3 * ids[i] + r]);
      }
    }
    if (!ok)
    {
      ++this->NonFinite;
      continue;
    }
    x.assign(3 * static_cast<size_t>(nodes), 0.0);
    s.assign(static_cast<size_t>(nodes), 0.0);
    if (native)
    {
      for (int i = 0; i < nodes; ++i)
      {
        std::copy_n(&this->Points[3 * ids[i]], 3, &x[3 * i]);
        s[i] = cellScalars ? cellValue : this->Scalars[ids[i]];
      }
    }
    else
    {
      grid->GetCell(c, source);
      w.resize(static_cast<size_t>(n));
      for (int k = 0; k < nodes; ++k)
      {
        double pc[3];
        basis.NodeParametricCoords(k, pc);
        source->InterpolateFunctions(pc, w.data());
        for (vtkIdType i = 0; i < n; ++i)
        {
          for (int r = 0; r < 3; ++r)
          {
            x[3 * k + r] += w[i] * this->Points[3 * ids[i] + r];
          }
          s[k] += w[i] * this->Scalars[ids[i]];
        }
        s[k] = cellScalars ? cellValue : s[k];
      }
    }
    const bool collapsed = type == VTK_PYRAMID || type == VTK_QUADRATIC_PYRAMID;
    if (CheckJacobian(it->second, x.data(), collapsed) <= 0)
    {
      ++this->Inverted;
      continue;
    }
    if (native && !cellScalars)
    {
      this->Connectivity.insert(this->Connectivity.end(), ids, ids + n);
      ++this->Native;
    }
    else
    {
      const std::int64_t first = static_cast<std::int64_t>(this->Scalars.size());
      this->Points.insert(this->Points.end(), x.begin(), x.end());
      this->Scalars.insert(this->Scalars.end(), s.begin(), s.end());
      for (int k = 0; k < nodes; ++k)
      {
        this->Connectivity.push_back(first + k);
      }
      ++(native ? this->Native : this->Converted);
    }
    this->Offsets.push_back(static_cast<std::int64_t>(this->Connectivity.size()));
    this->Types.push_back(static_cast<unsigned char>(lagrangeType));
    this->Degrees.insert(this->Degrees.end(), deg, deg + 3);
  }
  if (!useDegrees)
  {
    // Orders from the node counts (the converted cells' counts give theirs).
    this->Degrees.clear();
  }
  return this->Native + this->Converted;
}

std::string hov::RayCastCells::Summary() const
{
  std::string out;
  if (this->Unsupported)
  {
    out += std::to_string(this->Unsupported) + " cells of types the ray caster does not handle " +
      "(first type: " + std::to_string(this->FirstUnsupportedType) +
      "; handled: 10-14, 24-27, 29, 32, 71-73, 78-80)";
  }
  if (this->Rational)
  {
    out += (out.empty() ? "" : ", ") + std::to_string(this->Rational) +
      " rational Bezier cells (RationalWeights other than 1: not polynomial)";
  }
  if (this->NonFinite)
  {
    out += (out.empty() ? "" : ", ") + std::to_string(this->NonFinite) +
      " with NaN/Inf points or scalars, bad point ids or node counts";
  }
  if (this->Inverted)
  {
    out += (out.empty() ? "" : ", ") + std::to_string(this->Inverted) +
      " inverted or degenerate (Jacobian <= 0 or mixed signs at the nodes)";
  }
  return out;
}
