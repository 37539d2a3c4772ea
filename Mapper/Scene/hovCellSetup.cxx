#include "hovCellSetup.h"

#include "hovCellShapes.h" // IsSupportedCellType

#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkNew.h" // the sort grid of a subset
#include "vtkPoints.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkUnstructuredGrid.h"     // the sort grid of a subset
#include "vtkUnstructuredGridBase.h"

#include <algorithm> // std::sort, std::swap
#include <cmath>     // std::isfinite, std::sqrt

namespace
{
// |6V| below this fraction of (longest edge)^3 is a degenerate tetrahedron
// (its shape is numerically a triangle or less; a regular tetrahedron has 0.12).
constexpr double DegenerateRelativeVolume = 1e-12;

enum Status : unsigned char
{
  Ok = 0,
  NotTetra,   // another supported type: hov::GeneralCells
  Unsupported,
  BadPoint,
  BadScalar,
  Degenerate
};

double ScalarOf(vtkDataArray* array, vtkIdType id, int component, double* tuple)
{
  const int nc = array->GetNumberOfComponents();
  if (nc == 1)
  {
    return array->GetComponent(id, 0);
  }
  array->GetTuple(id, tuple);
  if (component >= 0 && component < nc)
  {
    return tuple[component];
  }
  double sum = 0.0;
  for (int c = 0; c < nc; ++c)
  {
    sum += tuple[c] * tuple[c];
  }
  return std::sqrt(sum);
}

using Tetra = hov::CellSetup::Tetra;

/**
 * Tetrahedron @p cellId with point ids @p ids into @p tet (point ids, linear
 * field); its status, and whether it is @p inverted (negative VTK orientation).
 */
Status PrepareTetra(vtkIdList* ids, vtkIdType cellId, const std::vector<glm::dvec3>& points,
  const std::vector<double>& values, bool cellScalars, Tetra& tet, unsigned char& inverted)
{
  if (ids->GetNumberOfIds() != 4)
  {
    return BadPoint; // broken connectivity
  }
  const vtkIdType numPoints = static_cast<vtkIdType>(points.size());
  glm::dvec3 x[4];
  double s[4];
  bool finitePoints = true, finiteScalars = true;
  for (int v = 0; v < 4 && finitePoints; ++v)
  {
    tet.Points[v] = ids->GetId(v);
    if (tet.Points[v] < 0 || tet.Points[v] >= numPoints)
    {
      finitePoints = false; // broken connectivity
      break;
    }
    x[v] = points[tet.Points[v]];
    finitePoints =
      finitePoints && std::isfinite(x[v].x) && std::isfinite(x[v].y) && std::isfinite(x[v].z);
    s[v] = cellScalars ? values[cellId] : values[tet.Points[v]];
    finiteScalars = finiteScalars && std::isfinite(s[v]);
  }
  if (!finitePoints)
  {
    return BadPoint;
  }
  if (!finiteScalars)
  {
    return BadScalar;
  }
  const glm::dvec3 e1 = x[1] - x[0], e2 = x[2] - x[0], e3 = x[3] - x[0];
  const double det = glm::dot(glm::cross(e1, e2), e3); // 6 V, VTK orientation
  double edge = 0.0;
  for (int a = 0; a < 4; ++a)
  {
    for (int b = a + 1; b < 4; ++b)
    {
      edge = std::max(edge, glm::length(x[b] - x[a]));
    }
  }
  if (!(std::abs(det) > DegenerateRelativeVolume * edge * edge * edge))
  {
    return Degenerate;
  }
  inverted = det < 0.0;
  // Linear field: solve [e1 e2 e3]^T g = (s1 - s0, s2 - s0, s3 - s0) by Cramer.
  tet.RefScalar = s[0];
  tet.ScalarMin = std::min(std::min(s[0], s[1]), std::min(s[2], s[3]));
  tet.ScalarMax = std::max(std::max(s[0], s[1]), std::max(s[2], s[3]));
  if (cellScalars)
  {
    tet.Gradient = glm::dvec3(0.0);
  }
  else
  {
    const glm::dvec3 c23 = glm::cross(e2, e3), c31 = glm::cross(e3, e1), c12 = glm::cross(e1, e2);
    tet.Gradient = ((s[1] - s[0]) * c23 + (s[2] - s[0]) * c31 + (s[3] - s[0]) * c12) / det;
  }
  tet.CellId = cellId;
  return Ok;
}
}

std::string hov::CellSetup::ShortScalars(
  vtkDataSet* grid, vtkDataArray* scalars, bool cellScalars)
{
  const vtkIdType needed = cellScalars ? grid->GetNumberOfCells() : grid->GetNumberOfPoints();
  if (scalars->GetNumberOfTuples() >= needed)
  {
    return std::string();
  }
  return std::string("scalar array '") + (scalars->GetName() ? scalars->GetName() : "") +
    "' has " + std::to_string(scalars->GetNumberOfTuples()) + " tuples for " +
    std::to_string(needed) + (cellScalars ? " cells" : " points");
}

bool hov::CellSetup::ReadInput(vtkUnstructuredGridBase* grid, vtkDataArray* scalars,
  bool cellScalars, int component, std::vector<double>& values, std::string* error)
{
  const vtkIdType numPoints = grid->GetNumberOfPoints();
  // One scalar per point (or per cell): component or magnitude.
  const vtkIdType numValues = cellScalars ? grid->GetNumberOfCells() : numPoints;
  const std::string shortArray = ShortScalars(grid, scalars, cellScalars);
  if (!shortArray.empty())
  {
    if (error)
    {
      *error = shortArray;
    }
    return false;
  }
  values.resize(numValues);
  const int nc = scalars->GetNumberOfComponents();
  vtkSMPTools::For(0, numValues, [&](vtkIdType begin, vtkIdType end) {
    std::vector<double> tuple(nc);
    for (vtkIdType i = begin; i < end; ++i)
    {
      values[i] = ScalarOf(scalars, i, component, tuple.data());
    }
  });
  vtkPoints* points = grid->GetPoints();
  this->Points.resize(numPoints);
  vtkSMPTools::For(0, numPoints, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      double p[3];
      points->GetPoint(i, p);
      this->Points[i] = glm::dvec3(p[0], p[1], p[2]);
    }
  });
  return true;
}

bool hov::CellSetup::Build(vtkUnstructuredGridBase* grid, vtkDataArray* scalars,
  bool cellScalars, int component, std::string* error)
{
  this->Stats = Statistics();
  this->SortGrid = nullptr;
  this->Tetras.clear();
  this->Points.clear();
  this->General.Build(nullptr, this->Points, {}, false, {});
  if (!grid || !scalars || !grid->GetPoints())
  {
    return false;
  }
  const vtkIdType numCells = grid->GetNumberOfCells();
  this->Stats.Cells = numCells;
  std::vector<double> values;
  if (!this->ReadInput(grid, scalars, cellScalars, component, values, error))
  {
    return false;
  }
  std::vector<Tetra> all(numCells);
  std::vector<unsigned char> status(numCells);
  std::vector<unsigned char> inverted(numCells, 0);
  vtkSMPThreadLocalObject<vtkIdList> localIds;
  vtkSMPTools::For(0, numCells, [&](vtkIdType begin, vtkIdType end) {
    vtkIdList* ids = localIds.Local();
    for (vtkIdType cellId = begin; cellId < end; ++cellId)
    {
      const int type = grid->GetCellType(cellId);
      if (type != VTK_TETRA)
      {
        status[cellId] = hov::IsSupportedCellType(type) ? NotTetra : Unsupported;
        continue;
      }
      grid->GetCellPoints(cellId, ids);
      status[cellId] = PrepareTetra(
        ids, cellId, this->Points, values, cellScalars, all[cellId], inverted[cellId]);
    }
  });

  // Compact, keeping input order; count problems.
  vtkIdType next = 0;
  std::vector<vtkIdType> generalIds;
  for (vtkIdType cellId = 0; cellId < numCells; ++cellId)
  {
    switch (status[cellId])
    {
      case Ok:
        break;
      case NotTetra:
        generalIds.push_back(cellId);
        continue;
      case Unsupported:
        if (this->Stats.Unsupported++ == 0)
        {
          this->Stats.FirstUnsupportedType = grid->GetCellType(cellId);
        }
        continue;
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
    this->Stats.Inverted += inverted[cellId];
    if (next != cellId)
    {
      all[next] = all[cellId];
    }
    ++next;
  }
  all.resize(next);
  all.shrink_to_fit();
  this->Tetras.swap(all);

  // The other supported cells, in input order after the tetrahedra.
  this->General.Build(grid, this->Points, values, cellScalars, generalIds);
  const hov::GeneralCells::Statistics& gs = this->General.GetStatistics();
  this->Stats.General = gs.Rendered;
  this->Stats.NonFinitePoints += gs.NonFinitePoints;
  this->Stats.NonFiniteScalars += gs.NonFiniteScalars;
  this->Stats.Degenerate += gs.Degenerate;
  this->Stats.InvertedGeneral = gs.Inverted;
  this->Stats.Curved = gs.Curved;
  this->Stats.MaxCurvature = gs.MaxCurvature;
  this->BuildSortGrid(grid);
  this->Stats.Rendered = this->GetNumberOfRenderedCells();
  return this->Stats.Rendered > 0;
}

void hov::CellSetup::FacePlanes(
  const Tetra& tet, double nx[4], double ny[4], double nz[4], double offset[4]) const
{
  // The vertices by ascending point id (distinct: a cell that repeats a
  // point is degenerate and not kept); face k's are these without vertex k.
  int byId[4] = { 0, 1, 2, 3 };
  std::sort(byId, byId + 4, [&](int p, int q) { return tet.Points[p] < tet.Points[q]; });
  glm::dvec3 x[4];
  for (int v = 0; v < 4; ++v)
  {
    x[v] = this->Points[tet.Points[v]];
  }
  for (int k = 0; k < 4; ++k)
  {
    int f[3], m = 0;
    for (int v : byId)
    {
      if (v != k)
      {
        f[m++] = v;
      }
    }
    glm::dvec3 n = glm::cross(x[f[1]] - x[f[0]], x[f[2]] - x[f[0]]);
    double h = glm::dot(n, x[f[0]]);
    if (glm::dot(n, x[k]) > h)
    {
      n = -n;
      h = -h;
    }
    nx[k] = n.x;
    ny[k] = n.y;
    nz[k] = n.z;
    offset[k] = h;
  }
}

void hov::CellSetup::BuildSortGrid(vtkUnstructuredGridBase* grid)
{
  // Every input cell a rendered tetrahedron, in input order (the common
  // case): the input itself is the sort's grid (cell k = GetTetras()[k]), no
  // copy of its connectivity (80 MB at 2M tetrahedra).
  if (this->General.GetCells().empty() &&
    static_cast<vtkIdType>(this->Tetras.size()) == grid->GetNumberOfCells())
  {
    this->SortGrid = grid;
    return;
  }
  // Otherwise a grid of the valid cells only, tetrahedra first
  // (cell k = GetTetras()[k]), then the general cells with their own types.
  vtkNew<vtkUnstructuredGrid> sortGrid;
  sortGrid->SetPoints(grid->GetPoints());
  sortGrid->Allocate(this->GetNumberOfRenderedCells());
  for (const Tetra& tet : this->Tetras)
  {
    sortGrid->InsertNextCell(VTK_TETRA, 4, tet.Points);
  }
  for (const hov::GeneralCells::Cell& cell : this->General.GetCells())
  {
    sortGrid->InsertNextCell(
      static_cast<int>(cell.Shape), cell.NodeCount, this->General.GetNodeIds(cell));
  }
  this->SortGrid = sortGrid;
}
