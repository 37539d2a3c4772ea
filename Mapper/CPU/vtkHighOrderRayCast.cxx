// CPU ray-cast render path for curved Lagrange cells: see vtkHighOrderRayCast.h.
#include "vtkHighOrderRayCast.h"

#include "vtkHighOrderViewRays.h" // pixel rays

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkUnstructuredGrid.h"

#include <cstdint> // 64-bit connectivity copies
#include <vector>  // the converted arrays

bool vtkHighOrderRayCast::SetInput(
  vtkUnstructuredGrid* grid, vtkDataArray* scalars, std::string* message)
{
  this->Ready = false;
  if (!grid || !scalars || !grid->GetPoints() ||
    scalars->GetNumberOfTuples() != grid->GetNumberOfPoints())
  {
    if (message)
    {
      *message = "no grid, no points, or no point scalars with one value per point";
    }
    return false;
  }
  const vtkIdType np = grid->GetNumberOfPoints(), nc = grid->GetNumberOfCells();
  std::vector<double> points(3 * np), values(np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    grid->GetPoints()->GetPoint(i, &points[3 * i]);
    values[i] = scalars->GetComponent(i, 0);
  }
  std::vector<unsigned char> types(nc);
  std::vector<std::int64_t> offsets{ 0 }, connectivity;
  vtkDataArray* degreesArray = grid->GetCellData()->GetHigherOrderDegrees();
  std::vector<int> degrees;
  for (vtkIdType c = 0; c < nc; ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    grid->GetCellPoints(c, n, ids);
    connectivity.insert(connectivity.end(), ids, ids + n);
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    types[c] = static_cast<unsigned char>(grid->GetCellType(c));
    for (int k = 0; degreesArray && degreesArray->GetNumberOfComponents() == 3 && k < 3; ++k)
    {
      degrees.push_back(static_cast<int>(degreesArray->GetComponent(c, k)));
    }
  }
  hov::CurvedMeshInput input;
  input.Points = points.data();
  input.NumberOfPoints = np;
  input.Scalars = values.data();
  input.CellTypes = types.data();
  input.Offsets = offsets.data();
  input.Connectivity = connectivity.data();
  input.NumberOfCells = nc;
  input.Degrees = degrees.size() == static_cast<size_t>(3 * nc) ? degrees.data() : nullptr;
  this->Ready = this->Caster.Build(input, message);
  return this->Ready;
}

bool vtkHighOrderRayCast::Render(const vtkHighOrderViewRays& rays, const hov::TransferFunction& tf,
  const hov::CurvedSegmentSettings& settings, float* rgba, float* error, const float* depth) const
{
  if (!this->Ready || !rgba)
  {
    return false;
  }
  const int width = rays.GetWidth(), height = rays.GetHeight();
  vtkSMPTools::For(0, height, [&](vtkIdType jBegin, vtkIdType jEnd) {
    for (vtkIdType j = jBegin; j < jEnd; ++j)
    {
      for (int i = 0; i < width; ++i)
      {
        const size_t p = static_cast<size_t>(j) * width + i;
        double tMax = 0.0;
        const vtkHighOrderViewRays::Ray ray = rays.TracedPixelRay(
          i, static_cast<int>(j), depth ? static_cast<double>(depth[p]) : 1.0, tMax);
        hov::RGBA c;
        double e = 0.0;
        if (tMax > 0.0)
        {
          const double o[3] = { ray.Origin.x, ray.Origin.y, ray.Origin.z };
          const double d[3] = { ray.Direction.x, ray.Direction.y, ray.Direction.z };
          c = this->Caster.TraceRay(o, d, 0.0, tMax, tf, settings, &e);
        }
        rgba[4 * p] = static_cast<float>(c.R);
        rgba[4 * p + 1] = static_cast<float>(c.G);
        rgba[4 * p + 2] = static_cast<float>(c.B);
        rgba[4 * p + 3] = static_cast<float>(c.A);
        if (error)
        {
          error[p] = static_cast<float>(e);
        }
      }
    }
  });
  return true;
}
