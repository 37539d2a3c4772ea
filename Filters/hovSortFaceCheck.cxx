#include "hovSortFaceCheck.h"

#include "hovCellShapes.h" // cell types, corner counts
#include "hovRayCell.h"    // face corner tables

#include "vtkCamera.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h" // per-face planes in parallel
#include "vtkUnstructuredGrid.h"

#include <algorithm> // std::sort
#include <array>     // face keys
#include <cmath>     // std::sqrt
#include <vector>    // buffers

namespace
{
//------------------------------------------------------------------------------
/// One cell face: its sorted corner ids (the key), its cell and its corners in order.
struct FaceRecord
{
  std::array<vtkIdType, 4> Key;
  std::array<vtkIdType, 4> Corners;
  vtkIdType Cell;
  int Size;
};

/// The centroid of the corners of @p cell (ids in @p pts).
void CornerCentroid(vtkPoints* points, const vtkIdType* pts, int n, double c[3])
{
  c[0] = c[1] = c[2] = 0.0;
  for (int k = 0; k < n; ++k)
  {
    double p[3];
    points->GetPoint(pts[k], p);
    for (int j = 0; j < 3; ++j)
    {
      c[j] += p[j] / n;
    }
  }
}

// Corners of a supported type (hovCellShapes: quadratic cells use their corners).
int CornerCount(int type)
{
  return hov::IsSupportedCellType(type) ? hov::CellCornerCount(static_cast<hov::CellShape>(type))
                                        : 0;
}

/// All faces of the supported cells, sorted so that equal keys are adjacent.
std::vector<FaceRecord> CollectFaces(vtkUnstructuredGrid* input)
{
  std::vector<FaceRecord> faces;
  const vtkIdType n = input->GetNumberOfCells();
  faces.reserve(static_cast<size_t>(n) * 4);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < n; ++c)
  {
    const int type = input->GetCellType(c);
    if (!hov::IsSupportedCellType(type))
    {
      continue;
    }
    const hov::CellShape shape = static_cast<hov::CellShape>(type);
    input->GetCellPoints(c, ids);
    if (ids->GetNumberOfIds() < hov::CellCornerCount(shape))
    {
      continue;
    }
    for (int f = 0, nf = hov::CellFaceCount(shape); f < nf; ++f)
    {
      int corners[4];
      FaceRecord r;
      r.Cell = c;
      r.Size = hov::CellFaceCorners(shape, f, corners);
      r.Key.fill(-1);
      r.Corners.fill(-1);
      for (int k = 0; k < r.Size; ++k)
      {
        r.Corners[k] = r.Key[k] = ids->GetId(corners[k]);
      }
      std::sort(r.Key.begin(), r.Key.begin() + r.Size);
      faces.push_back(r);
    }
  }
  std::sort(faces.begin(), faces.end(), [](const FaceRecord& a, const FaceRecord& b) {
    return a.Key != b.Key ? a.Key < b.Key : a.Cell < b.Cell;
  });
  return faces;
}

/// The eye in data coordinates, homogeneous (w = 1: a point; w = 0: the point
/// at infinity behind a parallel camera), and the view direction in data coordinates.
struct DataEye
{
  double E[4];
  double Dop[3];
  bool Valid = false;
};

DataEye EyeInData(vtkCamera* camera, vtkMatrix4x4* model)
{
  DataEye eye;
  double world[4], dop[4] = { 0, 0, 0, 0 };
  camera->GetDirectionOfProjection(dop);
  if (camera->GetParallelProjection())
  {
    world[0] = -dop[0];
    world[1] = -dop[1];
    world[2] = -dop[2];
    world[3] = 0.0;
  }
  else
  {
    camera->GetPosition(world);
    world[3] = 1.0;
  }
  vtkNew<vtkMatrix4x4> inverse;
  if (model)
  {
    if (model->Determinant() == 0.0)
    {
      return eye;
    }
    vtkMatrix4x4::Invert(model, inverse);
  }
  inverse->MultiplyPoint(world, eye.E);
  double d[4];
  inverse->MultiplyPoint(dop, d);
  if (eye.E[3] != 0.0)
  {
    for (int j = 0; j < 4; ++j)
    {
      eye.E[j] /= eye.E[3];
    }
  }
  std::copy(d, d + 3, eye.Dop);
  eye.Valid = true;
  return eye;
}

/// Newell plane (unit normal, a point, maximum corner deviation) of a face.
void FacePlane(vtkPoints* points, const FaceRecord& f, double n[3], double c[3], double& dev)
{
  double p[4][3];
  for (int k = 0; k < f.Size; ++k)
  {
    points->GetPoint(f.Corners[k], p[k]);
  }
  n[0] = n[1] = n[2] = c[0] = c[1] = c[2] = 0.0;
  for (int k = 0; k < f.Size; ++k)
  {
    const double* a = p[k];
    const double* b = p[(k + 1) % f.Size];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    for (int j = 0; j < 3; ++j)
    {
      c[j] += a[j] / f.Size;
    }
  }
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  dev = 0.0;
  if (len == 0.0)
  {
    return;
  }
  for (int j = 0; j < 3; ++j)
  {
    n[j] /= len;
  }
  for (int k = 0; k < f.Size; ++k)
  {
    const double d =
      (p[k][0] - c[0]) * n[0] + (p[k][1] - c[1]) * n[1] + (p[k][2] - c[2]) * n[2];
    dev = std::max(dev, std::abs(d));
  }
}
}

namespace hovSort
{
//------------------------------------------------------------------------------
FaceCheckResult CheckInteriorFaces(vtkUnstructuredGrid* input, vtkCamera* camera,
  vtkMatrix4x4* model, vtkIdTypeArray* order)
{
  FaceCheckResult result;
  const DataEye eye = EyeInData(camera, model);
  vtkPoints* points = input->GetPoints();
  if (!eye.Valid || !points)
  {
    return result;
  }
  const vtkIdType n = input->GetNumberOfCells();
  std::vector<vtkIdType> rank(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    rank[order->GetValue(i)] = i;
  }
  const std::vector<FaceRecord> faces = CollectFaces(input);
  // Interior faces: a key shared by exactly two records.
  std::vector<size_t> pairs;
  for (size_t i = 0; i + 1 < faces.size();)
  {
    size_t j = i + 1;
    while (j < faces.size() && faces[j].Key == faces[i].Key)
    {
      ++j;
    }
    if (j - i == 2 && faces[i].Cell != faces[i + 1].Cell)
    {
      pairs.push_back(i);
    }
    i = j;
  }
  const bool perspective = eye.E[3] != 0.0;
  std::vector<char> verdict(pairs.size(), 0); // 0 skipped, 1 ok, 2 violation
  vtkSMPTools::For(0, static_cast<vtkIdType>(pairs.size()), [&](vtkIdType b, vtkIdType e) {
    vtkNew<vtkIdList> ids;
    for (vtkIdType p = b; p < e; ++p)
    {
      const FaceRecord& f = faces[pairs[p]];
      double nrm[3], c[3], dev;
      FacePlane(points, f, nrm, c, dev);
      if (nrm[0] == 0 && nrm[1] == 0 && nrm[2] == 0)
      {
        continue;
      }
      double toEye[3], eyeDist = 0;
      for (int j = 0; j < 3; ++j)
      {
        toEye[j] = perspective ? eye.E[j] - c[j] : eye.E[j];
        eyeDist += toEye[j] * toEye[j];
      }
      eyeDist = std::sqrt(eyeDist);
      const double sEye = nrm[0] * toEye[0] + nrm[1] * toEye[1] + nrm[2] * toEye[2];
      if (std::abs(sEye) <= (perspective ? dev : 0.0) + 1e-9 * eyeDist)
      {
        continue; // edge-on
      }
      if (perspective)
      {
        // Entirely behind the eye: no ray sees the face.
        double front = -1e300;
        for (int k = 0; k < f.Size; ++k)
        {
          double q[3];
          points->GetPoint(f.Corners[k], q);
          front = std::max(front,
            (q[0] - eye.E[0]) * eye.Dop[0] + (q[1] - eye.E[1]) * eye.Dop[1] +
              (q[2] - eye.E[2]) * eye.Dop[2]);
        }
        if (front <= 0.0)
        {
          continue;
        }
      }
      const vtkIdType cells[2] = { f.Cell, faces[pairs[p] + 1].Cell };
      double side[2];
      for (int k = 0; k < 2; ++k)
      {
        input->GetCellPoints(cells[k], ids);
        double g[3];
        CornerCentroid(points, ids->GetPointer(0), CornerCount(input->GetCellType(cells[k])), g);
        side[k] = nrm[0] * (g[0] - c[0]) + nrm[1] * (g[1] - c[1]) + nrm[2] * (g[2] - c[2]);
      }
      if (side[0] * side[1] >= 0.0)
      {
        continue; // both on one side: overlapping or inverted cells, no verdict
      }
      // The cell on the eye's side is in front; the other must come first.
      const int frontCell = (side[0] > 0) == (sEye > 0) ? 0 : 1;
      const bool ok = rank[cells[1 - frontCell]] < rank[cells[frontCell]];
      verdict[p] = ok ? 1 : 2;
    }
  });
  for (char v : verdict)
  {
    result.Checked += v != 0;
    result.Violations += v == 2;
  }
  return result;
}
}
