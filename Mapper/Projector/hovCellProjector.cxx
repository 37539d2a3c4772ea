#include "hovCellProjector.h"

#include "hovCellRecords.h"   // the records the tiles read
#include "hovCellSetup.h"     // the cells
#include "hovProjectorTile.h" // the per-tile work
#include "hovViewRays.h"      // pixel rays

#include "hovPixelRange.h"       // pixel boxes of far-off cells
#include "hovTransferFunction.h" // the table

#include "vtkSMPThreadLocal.h" // one tile per thread
#include "vtkSMPTools.h"       // the per-frame passes

#include <algorithm> // std::min, std::max
#include <utility>   // pair

/// Per-frame arrays kept across frames.
struct hov::CellProjector::Buffers
{
  ProjectedPoints Points;
  CellRecords Records; ///< and the pixel boxes, for binning
  std::vector<std::pair<float, vtkIdType>> DepthOrder; ///< per-pixel mode: (depth, tetra)
  std::vector<vtkIdType> Order;                        ///< per-pixel mode: tetras by depth
  std::vector<unsigned char> Covers; ///< per-pixel mode: the cell covers a pixel centre
  TileBins Bins;
  vtkSMPThreadLocal<ProjectorTile> Tiles;
};

namespace
{
using Box = hov::CellBox;
using Tetra = hov::CellSetup::Tetra;

/// Centroid of the corners of general cell @p g (per-pixel mode's depth key).
glm::dvec3 GeneralCentroid(const hov::CellSetup& setup, vtkIdType g)
{
  const hov::GeneralCells& cells = setup.GetGeneralCells();
  const hov::GeneralCells::Cell& cell = cells.GetCells()[g];
  const double* x = cells.GetNodes(cell);
  const int n = hov::CellCornerCount(cell.Shape);
  glm::dvec3 c(0.0);
  for (int v = 0; v < n; ++v)
  {
    c += glm::dvec3(x[3 * v], x[3 * v + 1], x[3 * v + 2]);
  }
  return c / static_cast<double>(n);
}
}

const std::vector<vtkIdType>& hov::CellProjector::DepthOrder(const CellSetup& setup,
  const std::vector<vtkIdType>& frontToBack, const ViewRays& rays) const
{
  // Per-pixel mode: any cell order gives the same image, since each pixel
  // sorts its own segments; cells by centroid depth along the central ray
  // make each pixel's list arrive nearly sorted (cheap insertion sort), and
  // sorting them once here keeps every tile's list in depth order and in
  // memory order at the same time.
  //
  // A tetrahedron whose pixel box holds no pixel centre adds nothing to any
  // pixel: it is left out here (most of a large mesh's cells in a reduced
  // interactive frame, whose few rays miss them), so neither the sort nor
  // the records nor the binning pay for it. The image is the same.
  Buffers& buf = *this->Scratch;
  const auto& tets = setup.GetTetras();
  const auto& points = setup.GetPoints();
  const vtkIdType numTets = static_cast<vtkIdType>(tets.size());
  const int width = rays.GetWidth(), height = rays.GetHeight();
  const ViewRays::Ray centre = rays.PixelRay(width / 2, height / 2);
  const vtkIdType n = static_cast<vtkIdType>(frontToBack.size());
  buf.DepthOrder.resize(frontToBack.size());
  buf.Covers.resize(frontToBack.size());
  vtkSMPTools::For(0, n, [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType k = b; k < e; ++k)
    {
      const vtkIdType id = frontToBack[k];
      if (id < numTets)
      {
        const Box box = CellRecords::TetraBox(tets[id].Points, buf.Points, width, height);
        buf.Covers[k] = box[0] <= box[1] && box[2] <= box[3];
        if (!buf.Covers[k])
        {
          continue;
        }
      }
      else
      {
        buf.Covers[k] = 1;
      }
      const glm::dvec3 c = id < numTets
        ? 0.25 * (points[tets[id].Points[0]] + points[tets[id].Points[1]] +
                   points[tets[id].Points[2]] + points[tets[id].Points[3]])
        : GeneralCentroid(setup, id - numTets);
      buf.DepthOrder[k] = { static_cast<float>(glm::dot(c - centre.Origin, centre.Direction)),
        frontToBack[k] };
    }
  });
  size_t kept = 0;
  for (size_t k = 0; k < buf.DepthOrder.size(); ++k)
  {
    if (buf.Covers[k])
    {
      buf.DepthOrder[kept++] = buf.DepthOrder[k];
    }
  }
  buf.DepthOrder.resize(kept);
  vtkSMPTools::Sort(buf.DepthOrder.begin(), buf.DepthOrder.end()); // (depth, id): deterministic
  buf.Order.resize(buf.DepthOrder.size());
  for (size_t k = 0; k < buf.Order.size(); ++k)
  {
    buf.Order[k] = buf.DepthOrder[k].second;
  }
  return buf.Order;
}

hov::CellProjector::Statistics hov::CellProjector::Render(const CellSetup& setup,
  const std::vector<vtkIdType>& frontToBack, const ViewRays& rays, const TransferFunction& tf,
  const Settings& settings, const float* depth, std::vector<double>& rgba) const
{
  const int width = rays.GetWidth(), height = rays.GetHeight();
  if (width <= 0 || height <= 0 || frontToBack.empty() || tf.GetNumberOfNodes() == 0)
  {
    rgba.assign(static_cast<size_t>(std::max(width, 0)) * std::max(height, 0) * 4, 0.0);
    return Statistics();
  }
  // The tiles cover the image and write every pixel: no need to clear it.
  rgba.resize(static_cast<size_t>(width) * height * 4);
  // Per-frame arrays live across frames: no allocation, no page faults.
  if (!this->Scratch)
  {
    this->Scratch = std::make_shared<Buffers>();
  }
  Buffers& buf = *this->Scratch;
  buf.Points.Project(rays, setup.GetPoints());
  const std::vector<vtkIdType>& order =
    settings.PerPixelSort ? this->DepthOrder(setup, frontToBack, rays) : frontToBack;
  // The general cells' frame data (their records only carry the pixel box).
  GeneralCellTile::FrameData general;
  general.Cells = &setup.GetGeneralCells();
  general.Window = buf.Points.Window.data();
  general.Perturbation = GeneralCellTile::PerturbationOf(rays);
  general.Projectable = buf.Points.Projectable.data();
  general.TF = &tf;
  general.Segment.Emission = settings.Integration.Emission;
  const vtkIdType transparent = buf.Records.Build(setup, order, buf.Points, tf, width, height,
    general, settings.RecordBudget, settings.SkipTransparent);
  buf.Bins.Build(buf.Records.GetBoxes(), width, height, TileSizeOf(settings));

  // Tiles in parallel; every pixel is composited by one thread in a fixed order.
  ProjectorTile::Frame frame;
  frame.Bins = &buf.Bins;
  frame.Cells = buf.Records.IsWhole() ? &buf.Records.GetRecords() : nullptr;
  frame.Records = &buf.Records;
  frame.TF = &tf;
  frame.Settings = &settings;
  frame.Rays = &rays;
  frame.Depth = depth;
  frame.WitnessTol = WitnessRelativeTolerance * rays.GetDepthScale();
  frame.PerturbX = rays.GetPerturbX();
  frame.PerturbY = rays.GetPerturbY();
  frame.General = setup.GetGeneralCells().GetCells().empty() ? nullptr : &general;
  Statistics stats = RunTiles(buf.Bins, width, height, settings.Progress, buf.Tiles, frame, rgba);
  stats.Content = buf.Bins.ContentBox(width, height); // tiles without cells are written zero
  stats.TransparentCells = transparent;
  if (buf.Records.IsWhole())
  {
    stats.Records = static_cast<vtkIdType>(buf.Records.GetRecords().size()) - transparent;
  }
  if (!buf.Records.IsWhole())
  {
    // A mesh beyond the record budget: its per-frame arrays (boxes, bins,
    // projected points: 80 MB for 2M tetrahedra; the per-pixel order) and
    // the tiles' record buffers are freed rather than kept for the next
    // frame, whose sort then does not add its buffers to them. Allocating
    // them again costs about 1% of such a frame.
    buf.Bins = TileBins();
    buf.Points = ProjectedPoints();
    std::vector<std::pair<float, vtkIdType>>().swap(buf.DepthOrder);
    std::vector<vtkIdType>().swap(buf.Order);
    std::vector<unsigned char>().swap(buf.Covers);
    for (ProjectorTile& tile : buf.Tiles)
    {
      tile.ReleaseLocalRecords();
    }
  }
  buf.Records.EndFrame();
  return stats;
}
