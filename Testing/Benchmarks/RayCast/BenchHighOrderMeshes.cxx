// Generated curved Lagrange meshes: see BenchHighOrderMeshes.h.
#include "BenchHighOrderMeshes.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkLagrangeHexahedron.h" // VTK's node order (GetParametricCoords)
#include "vtkLagrangeTetra.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>         // the curving map
#include <cstdint>       // node keys
#include <unordered_map> // node merging
#include <vector>

namespace
{
constexpr double Pi = 3.14159265358979323846;

void Curve(const double X[3], double x[3])
{
  const double r = 1.0 + 0.6 * X[0], theta = 1.2 * (X[1] - 0.5) + 0.3 * X[2];
  x[0] = r * std::cos(theta);
  x[1] = r * std::sin(theta);
  x[2] = 0.8 * X[2] + 0.15 * std::sin(Pi * X[0]) * std::sin(Pi * X[1]);
}

double Field(const double x[3])
{
  return std::sin(2.0 * x[0]) + x[2] * std::cos(3.0 * x[1]) + 0.5 * x[0] * x[1];
}

/// Builds the grid: nodes merged by their position on the reference grid of
/// spacing 1 / (n order) (exact integers), points curved, scalars sampled.
class Builder
{
public:
  Builder(int n, int order)
    : Steps(n * order)
  {
    this->Grid->SetPoints(this->Points);
    this->Scalars->SetName("f");
  }
  /// Adds a cell of @p type whose node k is at reference position
  /// corner0 + sum_d pc[3 k + d] axis_d (grid units of 1 / Steps).
  void AddCell(int type, int nodes, const double* pc, const double corner0[3],
    const double axes[3][3])
  {
    vtkNew<vtkIdList> ids;
    ids->SetNumberOfIds(nodes);
    for (int k = 0; k < nodes; ++k)
    {
      double g[3];
      for (int d = 0; d < 3; ++d)
      {
        g[d] = corner0[d] + pc[3 * k] * axes[0][d] + pc[3 * k + 1] * axes[1][d] +
          pc[3 * k + 2] * axes[2][d];
      }
      std::int64_t key = 0;
      for (int d = 0; d < 3; ++d)
      {
        key = key * (this->Steps + 1) + static_cast<std::int64_t>(std::llround(g[d]));
      }
      auto it = this->Index.find(key);
      if (it == this->Index.end())
      {
        const double X[3] = { g[0] / this->Steps, g[1] / this->Steps, g[2] / this->Steps };
        double x[3];
        Curve(X, x);
        it = this->Index.emplace(key, this->Points->InsertNextPoint(x)).first;
        this->Scalars->InsertNextValue(Field(x));
      }
      ids->SetId(k, it->second);
    }
    this->Grid->InsertNextCell(type, ids);
  }
  vtkSmartPointer<vtkUnstructuredGrid> Finish()
  {
    this->Grid->GetPointData()->SetScalars(this->Scalars);
    return this->Grid;
  }

private:
  int Steps;
  vtkSmartPointer<vtkUnstructuredGrid> Grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> Points;
  vtkNew<vtkDoubleArray> Scalars;
  std::unordered_map<std::int64_t, vtkIdType> Index;
};
}

namespace hovBench
{
vtkSmartPointer<vtkUnstructuredGrid> CurvedTetMesh(int n, int order)
{
  const int nodes = (order + 1) * (order + 2) * (order + 3) / 6;
  vtkNew<vtkLagrangeTetra> cell;
  cell->GetPointIds()->SetNumberOfIds(nodes);
  cell->GetPoints()->SetNumberOfPoints(nodes);
  cell->Initialize();
  const std::vector<double> pc(cell->GetParametricCoords(), cell->GetParametricCoords() + 3 * nodes);
  Builder b(n, order);
  // The 6 tetrahedra of a cube around its diagonal 0 -> 7 (Kuhn): corners
  // 0, e_a, e_a + e_b, e_0 + e_1 + e_2 for each permutation (a, b, c).
  const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 },
    { 2, 1, 0 } };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& p : perms)
        {
          const double c0[3] = { double(i * order), double(j * order), double(k * order) };
          double v1[3] = { 0, 0, 0 }, v2[3] = { 0, 0, 0 }, v3[3] = { 1, 1, 1 };
          v1[p[0]] = 1;
          v2[p[0]] = v2[p[1]] = 1;
          // Odd permutations: the first two corners swapped (positive orientation).
          const bool odd = (p[0] + 1) % 3 != p[1];
          double axes[3][3];
          for (int d = 0; d < 3; ++d)
          {
            axes[0][d] = order * (odd ? v2[d] : v1[d]);
            axes[1][d] = order * (odd ? v1[d] : v2[d]);
            axes[2][d] = order * v3[d];
          }
          b.AddCell(VTK_LAGRANGE_TETRAHEDRON, nodes, pc.data(), c0, axes);
        }
  return b.Finish();
}

vtkSmartPointer<vtkUnstructuredGrid> CurvedHexMesh(int n, int order)
{
  const int nodes = (order + 1) * (order + 1) * (order + 1);
  vtkNew<vtkLagrangeHexahedron> cell;
  cell->GetPointIds()->SetNumberOfIds(nodes);
  cell->GetPoints()->SetNumberOfPoints(nodes);
  cell->SetOrder(order, order, order);
  const std::vector<double> pc(cell->GetParametricCoords(), cell->GetParametricCoords() + 3 * nodes);
  Builder b(n, order);
  const double axes[3][3] = { { double(order), 0, 0 }, { 0, double(order), 0 },
    { 0, 0, double(order) } };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double c0[3] = { double(i * order), double(j * order), double(k * order) };
        b.AddCell(VTK_LAGRANGE_HEXAHEDRON, nodes, pc.data(), c0, axes);
      }
  vtkSmartPointer<vtkUnstructuredGrid> grid = b.Finish();
  vtkNew<vtkIntArray> degrees;
  degrees->SetName("HigherOrderDegrees");
  degrees->SetNumberOfComponents(3);
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    const int d[3] = { order, order, order };
    degrees->InsertNextTypedTuple(d);
  }
  grid->GetCellData()->SetHigherOrderDegrees(degrees);
  return grid;
}
}
