#include "hovBlendProjector.h"

#include "hovCellSetup.h"       // the cells
#include "hovGeneralCellTile.h" // general cells: intervals and pieces
#include "hovGeneralCells.h"    // general cells
#include "hovTileGeometry.h"    // ClipRayFaces
#include "hovViewRays.h"        // pixel rays

#include "hovPixelRange.h"       // pixel boxes
#include "hovTransferFunction.h" // the table

#include "vtkSMPThreadLocal.h" // one tile per thread
#include "vtkSMPTools.h"       // the per-frame passes

#include <algorithm> // std::min, std::max

namespace hov
{
namespace
{
/// What every tile of a blend frame reads.
struct BlendFrame
{
  const CellSetup* Setup = nullptr;
  const TileBins* Bins = nullptr;
  const std::vector<CellBox>* Boxes = nullptr;
  const ViewRays* Rays = nullptr;
  const float* Depth = nullptr;
  const TransferFunction* Table = nullptr;
  BlendSettings Blend;
  GeneralCellTile::FrameData General;
  std::vector<double>* Error = nullptr;
};

/// One tile's pixels and their blend states.
class BlendTile : public TilePixels
{
public:
  void Render(const BlendFrame& frame, int tileIndex, std::vector<double>& rgba,
    ProjectorStatistics& st)
  {
    const TileBins& bins = *frame.Bins;
    const int width = frame.Rays->GetWidth(), height = frame.Rays->GetHeight();
    if (bins.Start[tileIndex + 1] == bins.Start[tileIndex])
    {
      WriteEmptyTile(bins, width, height, tileIndex, rgba);
      this->WriteError(frame, bins, tileIndex, width, height, true);
      return;
    }
    this->InitPixels(*frame.Rays, frame.Depth, bins, tileIndex);
    this->States.assign(this->Rays.size(), RayBlendState());
    const vtkIdType numTets = static_cast<vtkIdType>(frame.Setup->GetTetras().size());
    for (vtkIdType k = bins.Start[tileIndex]; k < bins.Start[tileIndex + 1]; ++k)
    {
      const vtkIdType c = bins.Cells[k];
      if (c < numTets)
      {
        this->Tetra(frame, c, (*frame.Boxes)[c], st);
      }
      else
      {
        this->General(frame, static_cast<int>(c - numTets), (*frame.Boxes)[c], st);
      }
    }
    for (size_t p = 0; p < this->States.size(); ++p)
    {
      this->Accum[p] = ResolveBlend(this->States[p], frame.Blend, *frame.Table);
    }
    this->WritePixels(rgba, width, st);
    this->WriteError(frame, bins, tileIndex, width, height, false);
  }

private:
  void WriteError(const BlendFrame& frame, const TileBins& bins, int tileIndex, int width,
    int height, bool empty) const
  {
    if (!frame.Error)
    {
      return;
    }
    const int x0 = (tileIndex % bins.TilesX) * bins.Size, y0 = (tileIndex / bins.TilesX) * bins.Size;
    const int w = std::min(bins.Size, width - x0), h = std::min(bins.Size, height - y0);
    for (int j = 0; j < h; ++j)
    {
      for (int i = 0; i < w; ++i)
      {
        (*frame.Error)[static_cast<size_t>(y0 + j) * width + x0 + i] =
          empty ? 0.0 : this->States[static_cast<size_t>(j) * w + i].ErrorBound;
      }
    }
  }

  /// The pixels of the tile inside @p box, as (first, last) tile-local ranges.
  bool Clip(const CellBox& box, int& i0, int& i1, int& j0, int& j1) const
  {
    i0 = std::max(box[0] - this->X0, 0);
    i1 = std::min(box[1] - this->X0, this->W - 1);
    j0 = std::max(box[2] - this->Y0, 0);
    j1 = std::min(box[3] - this->Y0, this->H - 1);
    return i0 <= i1 && j0 <= j1;
  }

  void Tetra(const BlendFrame& frame, vtkIdType c, const CellBox& box, ProjectorStatistics& st)
  {
    int i0, i1, j0, j1;
    if (!this->Clip(box, i0, i1, j0, j1))
    {
      return;
    }
    const CellSetup::Tetra& tet = frame.Setup->GetTetras()[c];
    double nx[4], ny[4], nz[4], offset[4];
    frame.Setup->FacePlanes(tet, nx, ny, nz, offset);
    const glm::dvec3& px = frame.Rays->GetPerturbX();
    const glm::dvec3& py = frame.Rays->GetPerturbY();
    for (int j = j0; j <= j1; ++j)
    {
      for (int i = i0; i <= i1; ++i)
      {
        const size_t p = static_cast<size_t>(j) * this->W + i;
        const ViewRays::Ray& ray = this->Rays[p];
        double tIn, tOut;
        if (!(this->TMax[p] > 0.0) ||
          !tile::ClipRayFaces(nx, ny, nz, offset, ray, this->TMax[p], px, py, tIn, tOut))
        {
          continue;
        }
        // The composite path's field along the ray (hov::ProjectorTile).
        const double sAtOrigin =
          tet.RefScalar + glm::dot(tet.Gradient, ray.Origin - frame.Setup->RefPoint(tet));
        const double slope = glm::dot(tet.Gradient, ray.Direction);
        AccumulateLinearSegment(this->States[p], frame.Blend, *frame.Table, tIn, tOut - tIn,
          sAtOrigin + tIn * slope, sAtOrigin + tOut * slope);
        ++st.Segments;
        ++st.Pieces;
      }
    }
  }

  void General(const BlendFrame& frame, int g, const CellBox& box, ProjectorStatistics& st)
  {
    GeneralCellTile::TileRows rows{ this->X0, this->Y0, this->W, 0, this->H, this->Rays.data(),
      this->TMax.data() };
    const auto& hits = this->Cells.Collect(frame.General, g, box, rows, nullptr);
    for (const GeneralCellTile::Hit& hit : hits)
    {
      const ViewRays::Ray& ray = this->Rays[hit.Pixel];
      for (int k = 0; k < hit.Count; ++k)
      {
        const RayCellInterval& iv = this->Cells.Intervals()[hit.First + k];
        ++st.Segments;
        for (const RestrictedPiece& piece :
          this->Cells.Restrict(frame.General, g, ray, iv.T0, iv.T1))
        {
          AccumulatePolynomialSegment(this->States[hit.Pixel], frame.Blend, *frame.Table,
            piece.T0, piece.T1 - piece.T0, piece.S, piece.ErrorBound);
          ++st.Pieces;
        }
      }
    }
  }

  std::vector<RayBlendState> States;
  GeneralCellTile Cells;
};
}
}

/// Per-frame arrays kept across frames.
struct hov::BlendProjector::Buffers
{
  ProjectedPoints Points;
  std::vector<CellBox> Boxes; ///< per rendered cell
  TileBins Bins;
  vtkSMPThreadLocal<BlendTile> Tiles;
};

hov::ProjectorStatistics hov::BlendProjector::Render(const CellSetup& setup, const ViewRays& rays,
  const TransferFunction& table, const BlendSettings& blend, const ProjectorSettings& settings,
  const float* depth, std::vector<double>& rgba, std::vector<double>* error) const
{
  const int width = rays.GetWidth(), height = rays.GetHeight();
  const size_t pixels = static_cast<size_t>(std::max(width, 0)) * std::max(height, 0);
  rgba.assign(4 * pixels, 0.0);
  if (error)
  {
    error->assign(pixels, 0.0);
  }
  const vtkIdType numCells = setup.GetNumberOfRenderedCells();
  if (pixels == 0 || numCells == 0 || table.GetNumberOfNodes() == 0)
  {
    return ProjectorStatistics();
  }
  if (!this->Scratch)
  {
    this->Scratch = std::make_shared<Buffers>();
  }
  Buffers& buf = *this->Scratch;
  buf.Points.Project(rays, setup.GetPoints());
  BlendFrame frame;
  frame.Setup = &setup;
  frame.Rays = &rays;
  frame.Depth = depth;
  frame.Table = &table;
  frame.Blend = blend;
  frame.General.Cells = &setup.GetGeneralCells();
  frame.General.Window = buf.Points.Window.data();
  frame.General.Projectable = buf.Points.Projectable.data();
  frame.General.TF = &table;
  frame.General.Perturbation = GeneralCellTile::PerturbationOf(rays);
  frame.Error = error;
  // Pixel boxes: the composite path's (projected corners, BoxMargin).
  const auto& tets = setup.GetTetras();
  const vtkIdType numTets = static_cast<vtkIdType>(tets.size());
  buf.Boxes.resize(numCells);
  vtkSMPTools::For(0, numCells, [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType c = b; c < e; ++c)
    {
      if (c >= numTets)
      {
        bool projectable = true;
        buf.Boxes[c] = GeneralCellTile::PixelBox(
          frame.General, static_cast<int>(c - numTets), width, height, projectable);
        continue;
      }
      double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
      bool projectable = true;
      for (vtkIdType id : tets[c].Points)
      {
        projectable = projectable && buf.Points.Projectable[id];
        x0 = std::min(x0, buf.Points.Window[id].x);
        x1 = std::max(x1, buf.Points.Window[id].x);
        y0 = std::min(y0, buf.Points.Window[id].y);
        y1 = std::max(y1, buf.Points.Window[id].y);
      }
      buf.Boxes[c] = projectable ? PixelBoxOf(x0, x1, y0, y1, width, height, BoxMargin)
                                 : CellBox{ 0, width - 1, 0, height - 1 };
    }
  });
  buf.Bins.Build(buf.Boxes, width, height, TileSizeOf(settings));
  frame.Bins = &buf.Bins;
  frame.Boxes = &buf.Boxes;
  return RunTiles(buf.Bins, width, height, settings.Progress, buf.Tiles, frame, rgba);
}
