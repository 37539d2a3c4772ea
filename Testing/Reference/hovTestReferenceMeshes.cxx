// Meshes and images of the reference (hovTestReference.h): a single
// tetrahedron, cubes of tetrahedra with a linear field, and the checked
// access to a mapper's float image.
#include "hovTestReference.h"
#include "hovTestReferenceVector.h"

#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <sstream>
#include <utility>

namespace hovTestRef
{
vtkSmartPointer<vtkUnstructuredGrid> MakeTetra(const double pts[4][3], const double scalars[4])
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (int v = 0; v < 4; ++v)
  {
    points->InsertNextPoint(pts[v]);
    s->InsertNextValue(scalars[v]);
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  const vtkIdType ids[4] = { 0, 1, 2, 3 };
  grid->InsertNextCell(VTK_TETRA, 4, ids);
  grid->GetPointData()->SetScalars(s);
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> MakeCubeOfTetras(
  int n, const double origin[3], double size, int tetsPerCube, double a, const double g[3])
{
  const int np = n + 1;
  auto id = [np](int i, int j, int k) { return static_cast<vtkIdType>(i + np * (j + np * k)); };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (int k = 0; k < np; ++k)
  {
    for (int j = 0; j < np; ++j)
    {
      for (int i = 0; i < np; ++i)
      {
        const double x[3] = { origin[0] + size * i / n, origin[1] + size * j / n,
          origin[2] + size * k / n };
        points->InsertNextPoint(x);
        s->InsertNextValue(a + g[0] * x[0] + g[1] * x[1] + g[2] * x[2]);
      }
    }
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->GetPointData()->SetScalars(s);
  grid->Allocate(static_cast<vtkIdType>(n) * n * n * tetsPerCube);

  auto insert = [&](vtkIdType ids[4]) {
    double x[4][3];
    for (int v = 0; v < 4; ++v)
    {
      points->GetPoint(ids[v], x[v]);
    }
    const Vec3 e1 = Sub(FromDouble(x[1]), FromDouble(x[0]));
    const Vec3 e2 = Sub(FromDouble(x[2]), FromDouble(x[0]));
    const Vec3 e3 = Sub(FromDouble(x[3]), FromDouble(x[0]));
    if (Dot(Cross(e1, e2), e3) < 0)
    {
      std::swap(ids[1], ids[2]); // positive VTK orientation
    }
    grid->InsertNextCell(VTK_TETRA, 4, ids);
  };

  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        // Corner c = bit0 x + bit1 y + bit2 z.
        vtkIdType c[8];
        for (int b = 0; b < 8; ++b)
        {
          c[b] = id(i + (b & 1), j + ((b >> 1) & 1), k + ((b >> 2) & 1));
        }
        if (tetsPerCube == 6)
        {
          // Kuhn: paths 0 -> 7 along the axes in every order.
          const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 },
            { 2, 0, 1 }, { 2, 1, 0 } };
          for (const auto& p : perms)
          {
            const int b1 = 1 << p[0];
            const int b2 = b1 | (1 << p[1]);
            vtkIdType ids[4] = { c[0], c[b1], c[b2], c[7] };
            insert(ids);
          }
        }
        else
        {
          const bool even = (i + j + k) % 2 == 0;
          const int tets[2][5][4] = {
            { { 1, 2, 4, 7 }, { 0, 1, 2, 4 }, { 3, 1, 2, 7 }, { 5, 1, 4, 7 }, { 6, 2, 4, 7 } },
            { { 0, 3, 5, 6 }, { 1, 0, 3, 5 }, { 2, 0, 3, 6 }, { 4, 0, 5, 6 }, { 7, 3, 5, 6 } }
          };
          for (const auto& t : tets[even ? 0 : 1])
          {
            vtkIdType ids[4] = { c[t[0]], c[t[1]], c[t[2]], c[t[3]] };
            insert(ids);
          }
        }
      }
    }
  }
  return grid;
}

const float* ImagePixels(vtkImageData* image, int width, int height, std::string& why)
{
  if (!image)
  {
    why = "no image";
    return nullptr;
  }
  const int* dims = image->GetDimensions();
  if (dims[0] != width || dims[1] != height || dims[2] != 1)
  {
    std::ostringstream os;
    os << "image is " << dims[0] << "x" << dims[1] << "x" << dims[2] << ", expected " << width
       << "x" << height << "x1";
    why = os.str();
    return nullptr;
  }
  auto* rgba = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  if (!rgba || rgba->GetNumberOfComponents() != 4 ||
    rgba->GetNumberOfTuples() != static_cast<vtkIdType>(width) * height || !rgba->GetName() ||
    std::string(rgba->GetName()) != "RGBA")
  {
    why = "point scalars are not a 4-component float array named RGBA of the image's size";
    return nullptr;
  }
  return rgba->GetPointer(0);
}
}
