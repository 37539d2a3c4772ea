#include "hovTestMeshes.h"

#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <utility>

namespace hovTest
{
vtkIdType MeshBuilder::AddPoint(double x, double y, double z, double s)
{
  this->Points.push_back({ x, y, z });
  this->Scalars.push_back(s);
  return static_cast<vtkIdType>(this->Points.size() - 1);
}

void MeshBuilder::AddCell(int type, const std::vector<vtkIdType>& ids)
{
  this->Types.push_back(type);
  this->Cells.push_back(ids);
}

double MeshBuilder::SignedVolume6(const std::vector<vtkIdType>& t) const
{
  const auto& a = this->Points[t[0]];
  const auto& b = this->Points[t[1]];
  const auto& c = this->Points[t[2]];
  const auto& d = this->Points[t[3]];
  const double e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double e2[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double e3[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
  const double cr[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
    e1[0] * e2[1] - e1[1] * e2[0] };
  return cr[0] * e3[0] + cr[1] * e3[1] + cr[2] * e3[2];
}

void MeshBuilder::AddTet(vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d, bool inverted)
{
  std::vector<vtkIdType> t{ a, b, c, d };
  const double v = this->SignedVolume6(t);
  if ((v < 0.0) != inverted)
  {
    std::swap(t[1], t[2]);
  }
  this->AddCell(VTK_TETRA, t);
}

void MeshBuilder::AddTetBlock(int nx, int ny, int nz, const double o[3], const double size[3],
  const std::function<double(double, double, double)>& f, bool inverted)
{
  std::vector<vtkIdType> ids((nx + 1) * (ny + 1) * (nz + 1));
  for (int k = 0; k <= nz; ++k)
  {
    for (int j = 0; j <= ny; ++j)
    {
      for (int i = 0; i <= nx; ++i)
      {
        const double x = o[0] + size[0] * i / nx;
        const double y = o[1] + size[1] * j / ny;
        const double z = o[2] + size[2] * k / nz;
        ids[(k * (ny + 1) + j) * (nx + 1) + i] = this->AddPoint(x, y, z, f(x, y, z));
      }
    }
  }
  static const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 },
    { 2, 0, 1 }, { 2, 1, 0 } };
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        for (const auto& p : perms)
        {
          int c[3] = { i, j, k };
          vtkIdType v[4];
          v[0] = ids[(c[2] * (ny + 1) + c[1]) * (nx + 1) + c[0]];
          for (int s = 0; s < 3; ++s)
          {
            ++c[p[s]];
            v[s + 1] = ids[(c[2] * (ny + 1) + c[1]) * (nx + 1) + c[0]];
          }
          this->AddTet(v[0], v[1], v[2], v[3], inverted);
        }
      }
    }
  }
}

void MeshBuilder::AddLooseTet(const double p[4][3], const double svals[4])
{
  vtkIdType v[4];
  for (int i = 0; i < 4; ++i)
  {
    v[i] = this->AddPoint(p[i][0], p[i][1], p[i][2], svals[i]);
  }
  this->AddTet(v[0], v[1], v[2], v[3]);
}

vtkSmartPointer<vtkUnstructuredGrid> MeshBuilder::Grid(bool withScalars) const
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(static_cast<vtkIdType>(this->Points.size()));
  for (size_t i = 0; i < this->Points.size(); ++i)
  {
    pts->SetPoint(static_cast<vtkIdType>(i), this->Points[i].data());
  }
  grid->SetPoints(pts);
  grid->Allocate(static_cast<vtkIdType>(this->Cells.size()));
  for (size_t c = 0; c < this->Cells.size(); ++c)
  {
    grid->InsertNextCell(this->Types[c], static_cast<vtkIdType>(this->Cells[c].size()),
      this->Cells[c].data());
  }
  if (withScalars)
  {
    vtkNew<vtkDoubleArray> s;
    s->SetName("s");
    s->SetNumberOfTuples(static_cast<vtkIdType>(this->Scalars.size()));
    for (size_t i = 0; i < this->Scalars.size(); ++i)
    {
      s->SetValue(static_cast<vtkIdType>(i), this->Scalars[i]);
    }
    grid->GetPointData()->SetScalars(s);
  }
  return grid;
}

double DefaultField(double x, double y, double z)
{
  return x + 0.5 * y + 0.25 * z;
}

MeshBuilder UnitBlock(int n, bool inverted)
{
  MeshBuilder m;
  const double o[3] = { 0, 0, 0 }, size[3] = { 1, 1, 1 };
  m.AddTetBlock(n, n, n, o, size, DefaultField, inverted);
  return m;
}

//------------------------------------------------------------------------------
void MeshBuilder::Append(const MeshBuilder& other)
{
  const vtkIdType base = static_cast<vtkIdType>(this->Points.size());
  for (size_t v = 0; v < other.Points.size(); ++v)
  {
    this->AddPoint(other.Points[v][0], other.Points[v][1], other.Points[v][2], other.Scalars[v]);
  }
  for (size_t c = 0; c < other.Cells.size(); ++c)
  {
    std::vector<vtkIdType> ids = other.Cells[c];
    for (vtkIdType& id : ids)
    {
      id += base;
    }
    this->AddCell(other.Types[c], ids);
  }
}
}
