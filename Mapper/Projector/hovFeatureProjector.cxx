#include "hovFeatureProjector.h"

#include "hovCellSetup.h"   // the cells
#include "hovFeatureTile.h" // per-tile work
#include "hovFeatures.h"    // settings
#include "hovViewRays.h"    // rays, projection

#include "hovCellShapes.h"       // general cells' splat centre and scalars
#include "hovPixelRange.h"       // pixel boxes of far-off cells
#include "hovRayCell.h"          // faces (general cells' volume)
#include "hovTransferFunction.h" // centroid extinction/colour of splats

#include "vtkSMPThreadLocal.h" // one tile per thread
#include "vtkSMPTools.h"       // per-cell preparation in parallel

#include <algorithm> // std::min, std::max
#include <cmath>     // std::ceil, std::floor

struct hov::FeatureProjector::TileStore
{
  vtkSMPThreadLocal<hov::FeatureTile> Tiles;
};

namespace
{
/// Pixel centres of the window-coordinate box [x0, x1] x [y0, y1] (widened by BoxMargin).
hov::FeatureProjector::Box PixelBox(
  double x0, double x1, double y0, double y1, int width, int height)
{
  return hov::PixelBoxOf(x0, x1, y0, y1, width, height, hov::BoxMargin);
}

/// Cross-section (dataset units^2) of the ray bundle of pixel (i, j) on the
/// plane through @p c perpendicular to its ray, from the neighbouring rays.
double PixelCrossSection(const hov::ViewRays& rays, int i, int j, const glm::dvec3& c)
{
  const hov::ViewRays::Ray r0 = rays.PixelRay(i, j);
  const hov::ViewRays::Ray rx = rays.PixelRay(i + 1, j);
  const hov::ViewRays::Ray ry = rays.PixelRay(i, j + 1);
  const glm::dvec3 n = r0.Direction;
  auto onPlane = [&](const hov::ViewRays::Ray& r) {
    return r.Origin + (glm::dot(c - r.Origin, n) / glm::dot(r.Direction, n)) * r.Direction;
  };
  const glm::dvec3 p0 = onPlane(r0);
  return glm::length(glm::cross(onPlane(rx) - p0, onPlane(ry) - p0));
}
/**
 * Volume of a straight-edged general cell from its corners: tetrahedra from
 * corner 0 to the fan triangles of every face not containing it (exact for
 * convex cells with planar faces; a non-planar quad face counts as its two
 * triangles through one diagonal, an O(non-planarity) difference).
 */
double GeneralCellVolume(hov::CellShape shape, const double* x)
{
  double volume = 0.0;
  const int faces = hov::CellFaceCount(shape);
  const glm::dvec3 p0(x[0], x[1], x[2]);
  for (int f = 0; f < faces; ++f)
  {
    int c[4];
    const int n = hov::CellFaceCorners(shape, f, c);
    if (std::find(c, c + n, 0) != c + n)
    {
      continue;
    }
    auto at = [&](int k) { return glm::dvec3(x[3 * c[k]], x[3 * c[k] + 1], x[3 * c[k] + 2]) - p0; };
    for (int k = 1; k + 1 < n; ++k)
    {
      volume += std::abs(glm::dot(at(0), glm::cross(at(k), at(k + 1)))) / 6.0;
    }
  }
  return volume;
}

/// The splat data of general cell @p cell: volume, centre (the parametric
/// centre's position) and the scalars there.
void GeneralSplatCell(const hov::GeneralCells& cells, const hov::GeneralCells::Cell& cell,
  const std::vector<double>* colorField, glm::dvec3& centre, double& s1, double& s2, double& volume)
{
  const double* nodes = cells.GetNodes(cell);
  double pc[3], x[3];
  hov::CellParametricCenter(cell.Shape, pc);
  hov::EvaluateGeometry(cell.Shape, nodes, pc, x, nullptr);
  centre = glm::dvec3(x[0], x[1], x[2]);
  s1 = hov::InterpolateCellScalar(cell.Shape, cells.GetScalars(cell), pc);
  s2 = s1;
  if (colorField)
  {
    double values[hov::MaxCellNodes];
    const vtkIdType* ids = cells.GetNodeIds(cell);
    for (int i = 0; i < cell.NodeCount; ++i)
    {
      values[i] = (*colorField)[ids[i]];
    }
    s2 = hov::InterpolateCellScalar(cell.Shape, values, pc);
  }
  volume = GeneralCellVolume(cell.Shape, nodes);
}
}

hov::FeatureProjector::FeatureProjector()
  : Tiles(new TileStore)
{
}

hov::FeatureProjector::~FeatureProjector() = default;

void hov::FeatureProjector::PrepareCells(const hov::CellSetup& setup,
  const hov::ViewRays& rays, const hov::TransferFunction& tf,
  const hov::Features& features, hov::EmissionModel emission)
{
  Frame& f = this->F;
  const auto& tets = setup.GetTetras();
  const auto& points = setup.GetPoints();
  const vtkIdType numTets = static_cast<vtkIdType>(tets.size());
  const int width = rays.GetWidth(), height = rays.GetHeight();
  const size_t numCells = f.Order->size();
  f.Boxes.resize(numCells);
  f.SplatOf.assign(numCells, -1);
  std::vector<unsigned char> splat(numCells, 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(numCells), [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType k = b; k < e; ++k)
    {
      const vtkIdType cell = (*f.Order)[k];
      if (cell >= numTets)
      {
        bool projectable = true;
        const int g = static_cast<int>(cell - numTets);
        f.Boxes[k] = hov::GeneralCellTile::PixelBox(f.General, g, width, height, projectable);
        if (features.Splatting && projectable)
        {
          const auto& gc = setup.GetGeneralCells().GetCells()[g];
          double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
          for (int v = 0; v < hov::CellCornerCount(gc.Shape); ++v)
          {
            const glm::dvec2& w = this->Points.Window[gc.CornerIds[v]];
            x0 = std::min(x0, w.x);
            x1 = std::max(x1, w.x);
            y0 = std::min(y0, w.y);
            y1 = std::max(y1, w.y);
          }
          splat[k] = (x1 - x0) * (y1 - y0) < features.SplatPixelThreshold &&
            std::max(x1 - x0, y1 - y0) <= hov::Features::SplatMaxSide;
        }
        continue;
      }
      const auto& tet = tets[cell];
      double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
      bool projectable = true;
      for (vtkIdType id : tet.Points)
      {
        projectable = projectable && this->Points.Projectable[id];
        x0 = std::min(x0, this->Points.Window[id].x);
        x1 = std::max(x1, this->Points.Window[id].x);
        y0 = std::min(y0, this->Points.Window[id].y);
        y1 = std::max(y1, this->Points.Window[id].y);
      }
      f.Boxes[k] = projectable ? PixelBox(x0, x1, y0, y1, width, height)
                               : Box{ 0, width - 1, 0, height - 1 };
      splat[k] = features.Splatting && projectable &&
        (x1 - x0) * (y1 - y0) < features.SplatPixelThreshold &&
        std::max(x1 - x0, y1 - y0) <= hov::Features::SplatMaxSide;
    }
  });
  f.Splats.clear();
  if (!features.Splatting)
  {
    return;
  }
  // The splats, in order (serially: their indices are deterministic).
  f.Splats.clear();
  for (size_t k = 0; k < numCells; ++k)
  {
    if (splat[k])
    {
      f.SplatOf[k] = static_cast<int>(f.Splats.size());
      f.Splats.emplace_back();
    }
  }
  const bool wvg = emission == hov::EmissionModel::WilhelmsVanGelder;
  vtkSMPTools::For(0, static_cast<vtkIdType>(numCells), [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType k = b; k < e; ++k)
    {
      if (f.SplatOf[k] < 0)
      {
        continue;
      }
      const vtkIdType cell = (*f.Order)[k];
      hov::SplatCell sc;
      glm::dvec3 c;
      double s1 = 0.0, s2 = 0.0;
      if (cell < numTets)
      {
        const auto& tet = tets[cell];
        const glm::dvec3 p0 = points[tet.Points[0]];
        c = 0.25 * (p0 + points[tet.Points[1]] + points[tet.Points[2]] + points[tet.Points[3]]);
        sc.Volume = std::abs(glm::dot(points[tet.Points[1]] - p0,
                      glm::cross(points[tet.Points[2]] - p0, points[tet.Points[3]] - p0))) / 6.0;
        // HIAC: extinction and colour at the centroid (exact mean of a linear field).
        s1 = tet.RefScalar + glm::dot(tet.Gradient, c - p0);
        s2 = s1;
        if (!this->TetColor.empty())
        {
          const auto& field = this->TetColor[cell];
          s2 = field.RefScalar + glm::dot(field.Gradient, c - p0);
        }
      }
      else
      {
        const hov::GeneralCells& cells = setup.GetGeneralCells();
        GeneralSplatCell(cells, cells.GetCells()[cell - numTets], features.ColorField, c, s1, s2,
          sc.Volume);
      }
      hov::SegmentEnd end;
      tf.Evaluate(tf.FindIntervalUpward(s1), s1, wvg, end);
      sc.Tau = end.Tau;
      if (s2 != s1)
      {
        tf.Evaluate(tf.FindIntervalUpward(s2), s2, wvg, end);
      }
      std::copy(end.Color, end.Color + 3, sc.Color);
      double xw = 0.0, yw = 0.0;
      rays.Project(c, xw, yw);
      const int ci = static_cast<int>(std::floor(xw)), cj = static_cast<int>(std::floor(yw));
      const double area = PixelCrossSection(rays, ci, cj, c);
      Splat& s = f.Splats[f.SplatOf[k]];
      s.Center = c;
      s.Footprint = hov::SplatCellContribution(sc, area, xw - 0.5, yw - 0.5, emission);
      f.Boxes[k] = Box{ std::max(s.Footprint.X0, 0), std::min(s.Footprint.X0 + 2, width - 1),
        std::max(s.Footprint.Y0, 0), std::min(s.Footprint.Y0 + 2, height - 1) };
    }
  });
}

hov::FeatureProjector::Statistics hov::FeatureProjector::Render(const CellSetup& setup,
  const std::vector<vtkIdType>& frontToBack, const ViewRays& rays, const TransferFunction& tf,
  const Settings& settings, const Features& features, const float* depth, std::vector<double>& rgba)
{
  const int width = rays.GetWidth(), height = rays.GetHeight();
  rgba.assign(static_cast<size_t>(std::max(width, 0)) * std::max(height, 0) * 4, 0.0);
  if (width <= 0 || height <= 0 || frontToBack.empty() || tf.GetNumberOfNodes() == 0)
  {
    return Statistics();
  }
  this->Points.Project(rays, setup.GetPoints());
  // Separate fields over the tetrahedra (linear: one gradient per cell).
  this->TetColor.clear();
  this->TetIso.clear();
  if (features.ColorField)
  {
    FeatureSegment::TetraFields(setup, *features.ColorField, this->TetColor);
  }
  if (features.IsoField)
  {
    FeatureSegment::TetraFields(setup, *features.IsoField, this->TetIso);
  }
  Frame& f = this->F;
  f.Setup = &setup;
  f.Order = &frontToBack;
  f.Rays = &rays;
  f.Depth = depth;
  f.Settings = &settings;
  f.General = GeneralCellTile::FrameData();
  f.General.Cells = &setup.GetGeneralCells();
  f.General.Window = this->Points.Window.data();
  f.General.Projectable = this->Points.Projectable.data();
  f.General.TF = &tf;
  f.General.Perturbation = GeneralCellTile::PerturbationOf(rays);
  f.Segment = FeatureSegment::FrameData();
  f.Segment.Setup = &setup;
  f.Segment.Features = &features;
  f.Segment.TF = &tf;
  f.Segment.Segment.Emission = settings.Integration.Emission;
  f.Segment.TetColor = &this->TetColor;
  f.Segment.TetIso = &this->TetIso;
  f.WitnessTol = WitnessRelativeTolerance * rays.GetDepthScale();
  f.PerturbX = rays.GetPerturbX();
  f.PerturbY = rays.GetPerturbY();
  this->PrepareCells(setup, rays, tf, features, settings.Integration.Emission);
  f.Bins.Build(f.Boxes, width, height, TileSizeOf(settings));
  return RunTiles(f.Bins, width, height, settings.Progress, this->Tiles->Tiles, f, rgba);
}
