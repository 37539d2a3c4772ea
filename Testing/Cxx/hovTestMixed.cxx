#include "hovTestMixed.h"

#include "vtkHighOrderVolumeMapper.h"

#include "hovCellShapes.h" // node parametric coordinates, corner map

#include "vtkCamera.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"

#include <cmath>
#include <utility>

namespace hovTest
{
namespace
{
/// det(p[b] - p[a], p[c] - p[a], p[d] - p[a]).
double Det(const MeshBuilder& m, vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d)
{
  return m.SignedVolume6({ a, b, c, d });
}

/// Appends the higher-order nodes of @p shape at their straight-edged
/// positions (the corner map at the node's parametric coordinates).
void AddCell(MeshBuilder& m, hov::CellShape shape, std::vector<vtkIdType> corners, const Field& f)
{
  const int n = hov::CellNodeCount(shape);
  const int nc = hov::CellCornerCount(shape);
  std::vector<double> x(3 * static_cast<size_t>(n), 0.0);
  for (int v = 0; v < nc; ++v)
  {
    for (int c = 0; c < 3; ++c)
    {
      x[3 * v + c] = m.Points[corners[v]][c];
    }
  }
  for (int v = nc; v < n; ++v)
  {
    double pc[3], p[3];
    hov::CellNodeParametricCoords(shape, v, pc);
    hov::EvaluateGeometry(shape, x.data(), pc, p, nullptr);
    corners.push_back(m.AddPoint(p[0], p[1], p[2], f(p[0], p[1], p[2])));
  }
  m.AddCell(static_cast<int>(shape), corners);
}
}

const char* CubeSplitName(CubeSplit split)
{
  static const char* names[] = { "hexahedron", "quadratic hexahedron", "triquadratic hexahedron",
    "voxel", "2 wedges", "2 quadratic wedges", "6 pyramids", "6 quadratic pyramids",
    "6 tetrahedra", "6 quadratic tetrahedra" };
  return names[static_cast<int>(split)];
}

void AddCube(MeshBuilder& m, const std::array<vtkIdType, 8>& c, CubeSplit split, const Field& f)
{
  using hov::CellShape;
  switch (split)
  {
    case CubeSplit::Hexahedron:
    case CubeSplit::QuadraticHexahedron:
    case CubeSplit::TriQuadraticHexahedron:
    {
      std::vector<vtkIdType> h(c.begin(), c.end());
      if (Det(m, h[0], h[1], h[3], h[4]) < 0.0)
      {
        std::swap(h[1], h[3]);
        std::swap(h[5], h[7]);
      }
      const CellShape shape = split == CubeSplit::Hexahedron ? CellShape::Hexahedron
        : split == CubeSplit::QuadraticHexahedron          ? CellShape::QuadraticHexahedron
                                                           : CellShape::TriQuadraticHexahedron;
      AddCell(m, shape, h, f);
      break;
    }
    case CubeSplit::Voxel:
      m.AddCell(VTK_VOXEL, { c[0], c[1], c[3], c[2], c[4], c[5], c[7], c[6] });
      break;
    case CubeSplit::Wedges:
    case CubeSplit::QuadraticWedges:
    {
      const int halves[2][6] = { { 0, 1, 2, 4, 5, 6 }, { 0, 2, 3, 4, 6, 7 } };
      for (const auto& w : halves)
      {
        std::vector<vtkIdType> ids;
        for (int v : w)
        {
          ids.push_back(c[v]);
        }
        // VTK's wedge: the (0,1,2) normal points away from (3,4,5).
        if (Det(m, ids[0], ids[1], ids[2], ids[3]) > 0.0)
        {
          std::swap(ids[1], ids[2]);
          std::swap(ids[4], ids[5]);
        }
        AddCell(m, split == CubeSplit::Wedges ? CellShape::Wedge : CellShape::QuadraticWedge, ids, f);
      }
      break;
    }
    case CubeSplit::Pyramids:
    case CubeSplit::QuadraticPyramids:
    {
      double centre[3] = { 0, 0, 0 };
      for (vtkIdType id : c)
      {
        for (int k = 0; k < 3; ++k)
        {
          centre[k] += m.Points[id][k] / 8.0;
        }
      }
      const vtkIdType apex = m.AddPoint(centre[0], centre[1], centre[2], f(centre[0], centre[1], centre[2]));
      const int faces[6][4] = { { 0, 1, 2, 3 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 3, 2, 6, 7 },
        { 0, 3, 7, 4 }, { 1, 2, 6, 5 } };
      for (const auto& face : faces)
      {
        std::vector<vtkIdType> ids = { c[face[0]], c[face[1]], c[face[2]], c[face[3]], apex };
        if (Det(m, ids[0], ids[1], ids[3], ids[4]) < 0.0)
        {
          std::swap(ids[1], ids[3]);
        }
        AddCell(m, split == CubeSplit::Pyramids ? CellShape::Pyramid : CellShape::QuadraticPyramid,
          ids, f);
      }
      break;
    }
    case CubeSplit::Tetras:
    case CubeSplit::QuadraticTetras:
    {
      const int paths[6][2] = { { 1, 2 }, { 1, 5 }, { 4, 5 }, { 4, 7 }, { 3, 7 }, { 3, 2 } };
      for (const auto& p : paths)
      {
        std::vector<vtkIdType> ids = { c[0], c[p[0]], c[p[1]], c[6] };
        if (Det(m, ids[0], ids[1], ids[2], ids[3]) < 0.0)
        {
          std::swap(ids[1], ids[2]);
        }
        AddCell(m, split == CubeSplit::Tetras ? CellShape::Tetra : CellShape::QuadraticTetra, ids, f);
      }
      break;
    }
  }
}

std::vector<vtkIdType> AddLattice(MeshBuilder& m, int nx, int ny, int nz, const double o[3],
  const double a[3][3], const Field& f)
{
  std::vector<vtkIdType> ids;
  for (int k = 0; k <= nz; ++k)
  {
    for (int j = 0; j <= ny; ++j)
    {
      for (int i = 0; i <= nx; ++i)
      {
        double x[3];
        for (int r = 0; r < 3; ++r)
        {
          x[r] = o[r] + a[r][0] * i + a[r][1] * j + a[r][2] * k;
        }
        ids.push_back(m.AddPoint(x[0], x[1], x[2], f(x[0], x[1], x[2])));
      }
    }
  }
  return ids;
}

std::array<vtkIdType, 8> LatticeCube(
  const std::vector<vtkIdType>& ids, int nx, int ny, int i, int j, int k)
{
  auto at = [&](int a, int b, int c) { return ids[a + (nx + 1) * (b + (ny + 1) * c)]; };
  return { at(i, j, k), at(i + 1, j, k), at(i + 1, j + 1, k), at(i, j + 1, k),
    at(i, j, k + 1), at(i + 1, j, k + 1), at(i + 1, j + 1, k + 1), at(i, j + 1, k + 1) };
}

Image RenderDouble(
  vtkHighOrderVolumeMapper* mapper, vtkCamera* cam, vtkVolume* vol, int w, int h, int* status)
{
  const int ok = mapper->RenderImage(cam, vol, w, h);
  if (status)
  {
    *status = ok;
  }
  vtkNew<vtkDoubleArray> rgba;
  mapper->GetDoubleImage(rgba);
  Image img;
  if (rgba->GetNumberOfTuples() == static_cast<vtkIdType>(w) * h)
  {
    img.W = w;
    img.H = h;
    img.V.assign(rgba->GetPointer(0), rgba->GetPointer(0) + 4 * static_cast<size_t>(w) * h);
  }
  return img;
}

void OrthoRayPlaneCrossing(vtkCamera* cam, int n, int i, int j, int axis, double level, double p[3])
{
  // The ray through pixel (i, j) is p0 + t v, p0 on the plane through the
  // focal point perpendicular to v; VTK orthogonalises the view up.
  double f[3], up[3], v[3], right[3];
  cam->GetFocalPoint(f);
  cam->GetViewUp(up);
  cam->GetDirectionOfProjection(v);
  right[0] = v[1] * up[2] - v[2] * up[1];
  right[1] = v[2] * up[0] - v[0] * up[2];
  right[2] = v[0] * up[1] - v[1] * up[0];
  const double s = cam->GetParallelScale();
  const double u = (i + 0.5 - n / 2.0) * (2.0 * s / n), w = (j + 0.5 - n / 2.0) * (2.0 * s / n);
  const double nup[3] = { right[1] * v[2] - right[2] * v[1], right[2] * v[0] - right[0] * v[2],
    right[0] * v[1] - right[1] * v[0] };
  const double nr = std::sqrt(right[0] * right[0] + right[1] * right[1] + right[2] * right[2]);
  const double nu = std::sqrt(nup[0] * nup[0] + nup[1] * nup[1] + nup[2] * nup[2]);
  double p0[3];
  for (int k = 0; k < 3; ++k)
  {
    p0[k] = f[k] + u * right[k] / nr + w * nup[k] / nu;
  }
  const double t = (level - p0[axis]) / v[axis];
  for (int k = 0; k < 3; ++k)
  {
    p[k] = p0[k] + t * v[k];
  }
}
}
