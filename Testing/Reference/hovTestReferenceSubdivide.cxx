// Quadratic-tetrahedron meshes of hovTestReferenceGeneral.h: the block
// builder and the conforming 1 -> 8^k linear subdivision.
#include "hovTestReferenceGeneral.h"
#include "hovTestReferenceVector.h"

#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkQuadraticTetra.h" // shape functions at the new nodes
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <map>
#include <utility>

namespace hovTestRef
{
namespace
{
/// A node of a sub-tetrahedron: integer barycentric weights over the 4 corners.
using Bary = std::array<int, 4>;
using SubTet = std::array<Bary, 4>;

Bary Mid(const Bary& a, const Bary& b)
{
  return { (a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2, (a[3] + b[3]) / 2 };
}

/// One round of the regular (red) split, octahedron cut along m02-m13.
std::vector<SubTet> RedSplit(const std::vector<SubTet>& tets)
{
  std::vector<SubTet> out;
  out.reserve(8 * tets.size());
  for (const SubTet& p : tets)
  {
    const Bary m01 = Mid(p[0], p[1]), m02 = Mid(p[0], p[2]), m03 = Mid(p[0], p[3]);
    const Bary m12 = Mid(p[1], p[2]), m13 = Mid(p[1], p[3]), m23 = Mid(p[2], p[3]);
    out.push_back({ p[0], m01, m02, m03 });
    out.push_back({ m01, p[1], m12, m13 });
    out.push_back({ m02, m12, p[2], m23 });
    out.push_back({ m03, m13, m23, p[3] });
    out.push_back({ m01, m02, m03, m13 });
    out.push_back({ m01, m02, m12, m13 });
    out.push_back({ m02, m03, m13, m23 });
    out.push_back({ m02, m12, m13, m23 });
  }
  return out;
}

/// Global key of a node: (corner id, weight) pairs with weight > 0, sorted.
using NodeKey = std::array<std::pair<vtkIdType, int>, 4>;
NodeKey KeyOf(const Bary& b, const vtkIdType corners[4])
{
  NodeKey k;
  for (int i = 0; i < 4; ++i)
  {
    k[i] = b[i] > 0 ? std::make_pair(corners[i], b[i]) : std::make_pair(vtkIdType(-1), 0);
  }
  std::sort(k.begin(), k.end());
  return k;
}
}

vtkSmartPointer<vtkUnstructuredGrid> SubdivideQuadraticTetras(vtkUnstructuredGrid* grid, int levels)
{
  const int n = 1 << levels;
  std::vector<SubTet> pattern{ SubTet{ Bary{ n, 0, 0, 0 }, Bary{ 0, n, 0, 0 }, Bary{ 0, 0, n, 0 },
    Bary{ 0, 0, 0, n } } };
  for (int l = 0; l < levels; ++l)
  {
    pattern = RedSplit(pattern);
  }
  vtkDataArray* in = grid->GetPointData()->GetScalars();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName(in && in->GetName() ? in->GetName() : "s");
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->Allocate(grid->GetNumberOfCells() * static_cast<vtkIdType>(pattern.size()));
  std::map<NodeKey, vtkIdType> ids;
  vtkNew<vtkIdList> cellIds;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    if (grid->GetCellType(c) != VTK_QUADRATIC_TETRA)
    {
      continue;
    }
    grid->GetCellPoints(c, cellIds);
    vtkIdType corners[4];
    Vec3 x[4];
    for (int i = 0; i < 4; ++i)
    {
      corners[i] = cellIds->GetId(i);
      x[i] = FromDouble(grid->GetPoint(corners[i]));
    }
    double s[10];
    for (int i = 0; i < 10; ++i)
    {
      s[i] = in ? in->GetComponent(cellIds->GetId(i), 0) : 0.0;
    }
    auto nodeId = [&](const Bary& b) {
      const auto [it, inserted] = ids.emplace(KeyOf(b, corners), points->GetNumberOfPoints());
      if (inserted)
      {
        Vec3 p{ 0, 0, 0 };
        for (int i = 0; i < 4; ++i)
        {
          p = Add(p, Scale(x[i], Real(b[i]) / n));
        }
        points->InsertNextPoint(double(p[0]), double(p[1]), double(p[2]));
        const double pc[3] = { double(b[1]) / n, double(b[2]) / n, double(b[3]) / n };
        double w[10], v = 0;
        vtkQuadraticTetra::InterpolationFunctions(pc, w);
        for (int i = 0; i < 10; ++i)
        {
          v += w[i] * s[i];
        }
        scalars->InsertNextValue(v);
      }
      return it->second;
    };
    for (const SubTet& t : pattern)
    {
      vtkIdType tet[4];
      for (int v = 0; v < 4; ++v)
      {
        tet[v] = nodeId(t[v]);
      }
      Vec3 q[4];
      for (int v = 0; v < 4; ++v)
      {
        q[v] = FromDouble(points->GetPoint(tet[v]));
      }
      if (Dot(Cross(Sub(q[1], q[0]), Sub(q[2], q[0])), Sub(q[3], q[0])) < 0)
      {
        std::swap(tet[1], tet[2]);
      }
      out->InsertNextCell(VTK_TETRA, 4, tet);
    }
  }
  out->SetPoints(points);
  out->GetPointData()->SetScalars(scalars);
  return out;
}

vtkSmartPointer<vtkUnstructuredGrid> MakeQuadraticTetraBlock(
  int n, const double origin[3], double size, const std::function<double(const double*)>& f)
{
  const int np = n + 1;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  auto addPoint = [&](const double x[3]) {
    points->InsertNextPoint(x);
    s->InsertNextValue(f(x));
    return points->GetNumberOfPoints() - 1;
  };
  for (int k = 0; k < np; ++k)
  {
    for (int j = 0; j < np; ++j)
    {
      for (int i = 0; i < np; ++i)
      {
        const double x[3] = { origin[0] + size * i / n, origin[1] + size * j / n,
          origin[2] + size * k / n };
        addPoint(x);
      }
    }
  }
  std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> mids;
  auto mid = [&](vtkIdType a, vtkIdType b) {
    const auto key = std::minmax(a, b);
    auto it = mids.find(key);
    if (it != mids.end())
    {
      return it->second;
    }
    double pa[3], pb[3];
    points->GetPoint(a, pa);
    points->GetPoint(b, pb);
    const double m[3] = { (pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2 };
    return mids[key] = addPoint(m);
  };
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->Allocate(6 * n * n * n);
  const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 },
    { 2, 1, 0 } };
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        auto id = [&](int b) {
          return static_cast<vtkIdType>(
            (i + (b & 1)) + np * ((j + ((b >> 1) & 1)) + np * (k + ((b >> 2) & 1))));
        };
        for (const auto& p : perms)
        {
          const int b1 = 1 << p[0], b2 = b1 | (1 << p[1]);
          vtkIdType c[10] = { id(0), id(b1), id(b2), id(7) };
          Vec3 q[4];
          for (int v = 0; v < 4; ++v)
          {
            q[v] = FromDouble(points->GetPoint(c[v]));
          }
          if (Dot(Cross(Sub(q[1], q[0]), Sub(q[2], q[0])), Sub(q[3], q[0])) < 0)
          {
            std::swap(c[1], c[2]);
          }
          const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
          for (int e = 0; e < 6; ++e)
          {
            c[4 + e] = mid(c[edges[e][0]], c[edges[e][1]]);
          }
          grid->InsertNextCell(VTK_QUADRATIC_TETRA, 10, c);
        }
      }
    }
  }
  grid->SetPoints(points);
  grid->GetPointData()->SetScalars(s);
  return grid;
}
}
