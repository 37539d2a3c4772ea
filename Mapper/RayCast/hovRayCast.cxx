// CPU ray-cast render path for curved Lagrange cells: see hov::RayCast.h.
#include "hovRayCast.h"

#include "hovViewRays.h" // pixel rays

#include "vtkDataArray.h"
#include "vtkSMPTools.h"
#include "vtkUnstructuredGrid.h"

#include <atomic> // issue counters
#include <cmath>   // std::isfinite
#include <cstdint> // 64-bit connectivity

bool hov::RayCast::SetInput(vtkUnstructuredGrid* grid, vtkDataArray* scalars, int component,
  bool cellScalars, std::string* message)
{
  this->Ready = false;
  if (!grid || !scalars || !grid->GetPoints() ||
    scalars->GetNumberOfTuples() <
      (cellScalars ? grid->GetNumberOfCells() : grid->GetNumberOfPoints()))
  {
    if (message)
    {
      *message = "no grid, no points, or fewer scalars than points (cells)";
    }
    return false;
  }
  hov::RayCastCells& mesh = this->Mesh;
  mesh.Convert(grid, scalars, component, cellScalars);
  hov::CurvedMeshInput input;
  input.Points = mesh.Points.data();
  input.NumberOfPoints = static_cast<std::int64_t>(mesh.Scalars.size());
  input.Scalars = mesh.Scalars.data();
  input.CellTypes = mesh.Types.data();
  input.Offsets = mesh.Offsets.data();
  input.Connectivity = mesh.Connectivity.data();
  input.NumberOfCells = static_cast<std::int64_t>(mesh.Types.size());
  input.Degrees = mesh.Degrees.empty() ? nullptr : mesh.Degrees.data();
  std::string casterMessage;
  this->Ready = !mesh.Types.empty() && this->Caster.Build(input, &casterMessage);
  if (message)
  {
    *message = mesh.Summary();
    if (!casterMessage.empty())
    {
      *message += (message->empty() ? "" : "; ") + casterMessage;
    }
  }
  // The converted arrays are only read by Build(): keep the counts, free the rest.
  mesh.Points = std::vector<double>();
  mesh.Scalars = std::vector<double>();
  mesh.Connectivity = std::vector<std::int64_t>();
  return this->Ready;
}

bool hov::RayCast::Render(const hov::ViewRays& rays, const hov::TransferFunction& tf,
  const hov::CurvedSegmentSettings& settings, float* rgba, float* error, const float* depth,
  Issues* issues, const hov::ProgressFunction& progress, const hov::BlendSettings* blend,
  const std::vector<unsigned char>* skipCells) const
{
  // Flags of another caster (a stale cache) would be read out of bounds.
  const unsigned char* skip = skipCells &&
      static_cast<long long>(skipCells->size()) == this->Caster.GetNumberOfCells()
    ? skipCells->data()
    : nullptr;
  std::atomic<long long> notConverged(0), notFinite(0), traced(0), segments(0), breakpoints(0);
  if (!this->Ready || !rgba)
  {
    return false;
  }
  const int width = rays.GetWidth(), height = rays.GetHeight();
  // One row is one "tile" of the batch loop; rows not traced stay zero.
  const int rowsDone = hov::ForTileBatches(height, progress, [&](vtkIdType j) {
    {
      long long rowRays = 0, rowSegments = 0, rowBreakpoints = 0;
      for (int i = 0; i < width; ++i)
      {
        const size_t p = static_cast<size_t>(j) * width + i;
        double tMax = 0.0;
        const hov::ViewRays::Ray ray = rays.TracedPixelRay(
          i, static_cast<int>(j), depth ? static_cast<double>(depth[p]) : 1.0, tMax);
        hov::RGBA c;
        double e = 0.0;
        if (tMax > 0.0)
        {
          const double o[3] = { ray.Origin.x, ray.Origin.y, ray.Origin.z };
          const double d[3] = { ray.Direction.x, ray.Direction.y, ray.Direction.z };
          hov::CurvedRayStats stats;
          if (blend)
          {
            hov::RayBlendState state;
            this->Caster.TraceRayBlend(o, d, 0.0, tMax, tf, *blend, settings, state, &stats);
            c = hov::ResolveBlend(state, *blend, tf);
            e = state.ErrorBound;
          }
          else
          {
            c = this->Caster.TraceRay(o, d, 0.0, tMax, tf, settings, &e, &stats, skip);
          }
          if (!stats.Converged)
          {
            ++notConverged;
          }
          ++rowRays;
          rowSegments += stats.Segments;
          rowBreakpoints += stats.Breakpoints;
        }
        if (!(std::isfinite(c.R) && std::isfinite(c.G) && std::isfinite(c.B) &&
              std::isfinite(c.A) && std::isfinite(e)))
        {
          c = hov::RGBA(); // never a NaN pixel: report it through the error image
          e = 1.0;
          ++notFinite;
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
      traced += rowRays;
      segments += rowSegments;
      breakpoints += rowBreakpoints;
    }
  });
  if (issues)
  {
    issues->NotConverged = notConverged.load();
    issues->NotFinite = notFinite.load();
    issues->Rays = traced.load();
    issues->Segments = segments.load();
    issues->Breakpoints = breakpoints.load();
    issues->Aborted = rowsDone < height;
  }
  return true;
}

long long hov::RayCast::MarkInvisibleCells(const hov::TransferFunction& tf,
  hov::EmissionModel emission, std::vector<unsigned char>& flags) const
{
  const vtkIdType n = this->Ready ? static_cast<vtkIdType>(this->Caster.GetNumberOfCells()) : 0;
  flags.assign(static_cast<size_t>(n), 0);
  std::atomic<long long> count(0);
  vtkSMPTools::For(0, n, [&](vtkIdType begin, vtkIdType end) {
    long long local = 0;
    for (vtkIdType c = begin; c < end; ++c)
    {
      if (this->Caster.IsCellInvisible(c, tf, emission))
      {
        flags[static_cast<size_t>(c)] = 1;
        ++local;
      }
    }
    count += local;
  });
  return count.load();
}
