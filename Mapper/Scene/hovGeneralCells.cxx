#include "hovGeneralCells.h"

#include "hovCellRestriction.h" // IsGeometryAffine
#include "hovFieldGradient.h"   // CachedAffineFieldBasis
#include "hovRayCell.h"         // PlanarFaceMask

#include "vtkIdList.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkUnstructuredGridBase.h"

#include <algorithm> // std::min, std::max
#include <cmath>     // std::isfinite, std::abs

namespace
{
enum Status : unsigned char
{
  Ok = 0,
  BadPoint,
  BadScalar,
  Degenerate
};

/// Sign of det J at the centre for a valid, non-inverted cell of @p shape in
/// VTK's convention (the one vtkCellValidator checks): that of VTK's
/// reference cell (nodes at their parametric coordinates), except for wedges.
/// VTK's wedge has its (0,1,2) face normal pointing away from (3,4,5) (vtkWedge
/// doc; real meshes in VTK order, e.g. zoo_mixed_ccx.vtu), the opposite of
/// the orientation of its own parametric map.
double ReferenceOrientation(hov::CellShape shape)
{
  const double wedge = hov::GeometryShape(shape) == hov::CellShape::Wedge ? -1.0 : 1.0;
  const int n = hov::CellNodeCount(shape);
  std::vector<double> nodes(3 * static_cast<size_t>(n));
  for (int i = 0; i < n; ++i)
  {
    hov::CellNodeParametricCoords(shape, i, &nodes[3 * static_cast<size_t>(i)]);
  }
  double pc[3], x[3], jac[9];
  hov::CellParametricCenter(shape, pc);
  hov::EvaluateGeometry(shape, nodes.data(), pc, x, jac);
  const double det = jac[0] * (jac[4] * jac[8] - jac[5] * jac[7]) -
    jac[1] * (jac[3] * jac[8] - jac[5] * jac[6]) + jac[2] * (jac[3] * jac[7] - jac[4] * jac[6]);
  return det < 0.0 ? -wedge : wedge;
}

double Det3(const double j[9])
{
  return j[0] * (j[4] * j[8] - j[5] * j[7]) - j[1] * (j[3] * j[8] - j[5] * j[6]) +
    j[2] * (j[3] * j[7] - j[4] * j[6]);
}

/// The per-pixel work's view-independent data of a valid cell (class doc).
void PrepareRays(hov::GeneralCells::Cell& cell, const double* nodes, const double* scalars)
{
  cell.PlanarFaces = hov::PlanarFaceMask(cell.Shape, nodes);
  cell.Affine = hov::IsGeometryAffine(cell.Shape, nodes);
  double pc[3], x[3], j[9];
  hov::CellParametricCenter(cell.Shape, pc);
  hov::EvaluateGeometry(cell.Shape, nodes, pc, x, j);
  const double det = Det3(j);
  if (!(std::abs(det) > 0.0))
  {
    cell.Affine = false;
    return;
  }
  // Inverse by cofactors (the Jacobian is well conditioned: not degenerate).
  double* inv = cell.InverseJacobian;
  inv[0] = (j[4] * j[8] - j[5] * j[7]) / det;
  inv[1] = (j[2] * j[7] - j[1] * j[8]) / det;
  inv[2] = (j[1] * j[5] - j[2] * j[4]) / det;
  inv[3] = (j[5] * j[6] - j[3] * j[8]) / det;
  inv[4] = (j[0] * j[8] - j[2] * j[6]) / det;
  inv[5] = (j[2] * j[3] - j[0] * j[5]) / det;
  inv[6] = (j[3] * j[7] - j[4] * j[6]) / det;
  inv[7] = (j[1] * j[6] - j[0] * j[7]) / det;
  inv[8] = (j[0] * j[4] - j[1] * j[3]) / det;
  const double* basis = hov::CachedAffineFieldBasis(cell.Shape);
  if (cell.Affine && basis)
  {
    // The field as a polynomial in pcoords: per-pixel restriction without
    // expanding every shape function along the ray.
    hov::AffineFieldCoefficients(basis, cell.NodeCount, scalars, cell.Field);
  }
  else
  {
    cell.Affine = false; // no basis (pyramids are never affine)
  }
}

/// Per-cell result of the geometric checks.
struct GeometryCheck
{
  Status Result = Ok;
  bool Inverted = false;
  double Curvature = 0.0; ///< largest node deviation / size
};

GeometryCheck CheckGeometry(hov::CellShape shape, const double* nodes, double referenceSign)
{
  GeometryCheck out;
  const hov::CellShape geometry = hov::GeometryShape(shape);
  const int corners = hov::CellCornerCount(shape);
  // Cell size: the longest corner-to-corner distance.
  double size2 = 0.0;
  for (int a = 0; a < corners; ++a)
  {
    for (int b = a + 1; b < corners; ++b)
    {
      double d2 = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        const double d = nodes[3 * b + c] - nodes[3 * a + c];
        d2 += d * d;
      }
      size2 = std::max(size2, d2);
    }
  }
  const double size = std::sqrt(size2);
  const double tol = hov::GeneralCells::DegenerateRelativeVolume * size2 * size;
  double pc[3], x[3], jac[9];
  hov::CellParametricCenter(shape, pc);
  hov::EvaluateGeometry(shape, nodes, pc, x, jac);
  const double centre = Det3(jac) * referenceSign;
  if (!(std::abs(centre) > tol))
  {
    out.Result = Degenerate;
    return out;
  }
  // Tangled: a corner's determinant of the other sign (pyramid apex: always 0).
  for (int k = 0; k < corners; ++k)
  {
    if (geometry == hov::CellShape::Pyramid && k == 4)
    {
      continue;
    }
    hov::CellNodeParametricCoords(geometry, k, pc);
    hov::EvaluateGeometry(shape, nodes, pc, x, jac);
    const double det = Det3(jac) * referenceSign;
    if ((centre > 0.0 && det < -tol) || (centre < 0.0 && det > tol))
    {
      out.Result = Degenerate;
      return out;
    }
  }
  out.Inverted = centre < 0.0;
  // Higher-order nodes against their straight-edged positions.
  const int n = hov::CellNodeCount(shape);
  for (int i = corners; i < n; ++i)
  {
    hov::CellNodeParametricCoords(shape, i, pc);
    hov::EvaluateGeometry(shape, nodes, pc, x, nullptr);
    double d2 = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      const double d = nodes[3 * i + c] - x[c];
      d2 += d * d;
    }
    out.Curvature = std::max(out.Curvature, std::sqrt(d2) / size);
  }
  return out;
}
}

void hov::GeneralCells::Build(vtkUnstructuredGridBase* grid,
  const std::vector<glm::dvec3>& points, const std::vector<double>& values, bool cellScalars,
  const std::vector<vtkIdType>& cellIds)
{
  this->Stats = Statistics();
  this->Cells.clear();
  this->Nodes.clear();
  this->Scalars.clear();
  this->NodeIds.clear();
  const vtkIdType count = static_cast<vtkIdType>(cellIds.size());
  if (count == 0)
  {
    return;
  }
  double referenceSign[32];
  bool known[32] = {};
  // Offsets of every candidate's nodes in the pools (skipped cells leave a hole).
  std::vector<Cell> all(count);
  vtkIdType next = 0;
  for (vtkIdType k = 0; k < count; ++k)
  {
    const int type = grid->GetCellType(cellIds[k]);
    all[k].Shape = static_cast<hov::CellShape>(type);
    all[k].NodeCount = hov::CellNodeCount(all[k].Shape);
    all[k].CellId = cellIds[k];
    all[k].NodeOffset = next;
    next += all[k].NodeCount;
    if (!known[type])
    {
      referenceSign[type] = ReferenceOrientation(all[k].Shape);
      known[type] = true;
    }
  }
  this->Nodes.resize(3 * static_cast<size_t>(next));
  this->Scalars.resize(next);
  this->NodeIds.resize(next);
  const vtkIdType numPoints = static_cast<vtkIdType>(points.size());
  std::vector<unsigned char> status(count, Ok);
  std::vector<GeometryCheck> checks(count);
  vtkSMPThreadLocalObject<vtkIdList> localIds;
  vtkSMPTools::For(0, count, [&](vtkIdType begin, vtkIdType end) {
    vtkIdList* ids = localIds.Local();
    for (vtkIdType k = begin; k < end; ++k)
    {
      Cell& cell = all[k];
      grid->GetCellPoints(cell.CellId, ids);
      if (ids->GetNumberOfIds() != cell.NodeCount)
      {
        status[k] = BadPoint;
        continue;
      }
      double* x = this->Nodes.data() + 3 * cell.NodeOffset;
      double* s = this->Scalars.data() + cell.NodeOffset;
      vtkIdType* nodeIds = this->NodeIds.data() + cell.NodeOffset;
      bool finitePoints = true, finiteScalars = true;
      for (int v = 0; v < cell.NodeCount && finitePoints; ++v)
      {
        const vtkIdType id = ids->GetId(v);
        if (id < 0 || id >= numPoints)
        {
          finitePoints = false;
          break;
        }
        nodeIds[v] = id;
        for (int c = 0; c < 3; ++c)
        {
          x[3 * v + c] = points[id][c];
          finitePoints = finitePoints && std::isfinite(x[3 * v + c]);
        }
        s[v] = cellScalars ? values[cell.CellId] : values[id];
        finiteScalars = finiteScalars && std::isfinite(s[v]);
      }
      if (!finitePoints || !finiteScalars)
      {
        status[k] = finitePoints ? BadScalar : BadPoint;
        continue;
      }
      const int corners = hov::CellCornerCount(cell.Shape);
      for (int v = 0; v < 8; ++v)
      {
        cell.CornerIds[v] = v < corners ? static_cast<std::int64_t>(nodeIds[v]) : -1;
      }
      cell.ScalarMin = *std::min_element(s, s + cell.NodeCount);
      cell.ScalarMax = *std::max_element(s, s + cell.NodeCount);
      checks[k] = CheckGeometry(cell.Shape, x, referenceSign[static_cast<int>(cell.Shape)]);
      status[k] = checks[k].Result;
      if (status[k] == Ok)
      {
        PrepareRays(cell, x, s);
      }
    }
  });
  // Compact in the given order; count problems.
  this->Cells.reserve(count);
  for (vtkIdType k = 0; k < count; ++k)
  {
    switch (status[k])
    {
      case Ok:
        break;
      case BadPoint:
        ++this->Stats.NonFinitePoints;
        continue;
      case BadScalar:
        ++this->Stats.NonFiniteScalars;
        continue;
      default:
        ++this->Stats.Degenerate;
        continue;
    }
    this->Stats.Inverted += checks[k].Inverted;
    if (checks[k].Curvature > CurvedRelativeTolerance)
    {
      ++this->Stats.Curved;
    }
    this->Stats.MaxCurvature = std::max(this->Stats.MaxCurvature, checks[k].Curvature);
    this->Cells.push_back(all[k]);
  }
  this->Stats.Rendered = static_cast<vtkIdType>(this->Cells.size());
}

void hov::GeneralCells::AffineLine(const Cell& cell, const double* nodes, const double o[3],
  const double d[3], double t0, double start[3], double step[3])
{
  const double* inv = cell.InverseJacobian;
  double pc0[3], rel[3];
  hov::CellNodeParametricCoords(cell.Shape, 0, pc0);
  for (int k = 0; k < 3; ++k)
  {
    rel[k] = (o[k] - nodes[k]) + t0 * d[k];
  }
  for (int i = 0; i < 3; ++i)
  {
    start[i] = pc0[i] + (inv[3 * i] * rel[0] + inv[3 * i + 1] * rel[1] + inv[3 * i + 2] * rel[2]);
    step[i] = inv[3 * i] * d[0] + inv[3 * i + 1] * d[1] + inv[3 * i + 2] * d[2];
  }
}

void hov::GeneralCells::RestrictAffine(const Cell& cell, const double* nodes, const double o[3],
  const double d[3], double t0, double t1, hov::RestrictedPiece& piece)
{
  double start[3], step[3];
  AffineLine(cell, nodes, o, d, t0, start, step);
  piece = hov::RestrictedPiece();
  piece.T0 = t0;
  piece.T1 = t1;
  piece.S = hov::RestrictAffineField(cell.Field, start, step);
}
