/**
 * @class   hov::FeatureProjector
 * @brief   The CPU projection path with the features of hov::Features:
 *          embedded shaded isosurfaces, separate colour and isosurface
 *          fields, subpixel splatting (HIAC sections 5.1-5.3).
 *
 * Used by vtkHighOrderVolumeMapper instead of hov::CellProjector when
 * a feature is active (the fast tetrahedra path stays untouched, so with the
 * features off nothing changes). Same cells, same visibility order, same
 * rays, clipping and depth-buffer limits; every ray interval of every cell
 * (linear tetrahedra: exact clip against the same canonical face planes;
 * general cells: hov::GeneralCellTile::Collect) is integrated by
 * hov::FeatureSegment.
 *
 * Isosurface ownership along a pixel (HIAC 5.1, hov::SurfaceCrossings): a
 * segment includes a surface at its front (t = its entry) only where no
 * segment of the same pixel ended exactly there before, i.e. where the ray
 * enters the mesh (or re-enters it, or starts at a clipping plane); shared
 * faces give bit-identical exit/entry times, so a surface lying on a shared
 * face is drawn exactly once, by the cell in front. Both orderings: in cell
 * order the previous segment of a pixel is the one composited before; per
 * pixel it is the previous one in the pixel's entry-sorted list.
 *
 * Splatting (Features::Splatting, HIAC 5.3): a cell whose projected
 * (corners') bounding box has an area below SplatPixelThreshold (pixels^2)
 * and sides of at most SplatMaxSide pixels is not ray-traced: its volume
 * (tetrahedra exact; general cells: tetrahedra from corner 0 to the faces'
 * fan triangles, exact for planar faces), the extinction and colour of the
 * transfer function at its centroid's scalar(s) (general cells: at the
 * parametric centre) and the cross-section of one pixel's ray bundle there
 * (from the neighbouring pixel rays: orthographic and perspective alike,
 * any affine volume matrix) give hov::SplatCellContribution, a 3 x 3
 * biquadratic B-spline footprint composited in the cell's turn (cell order;
 * per pixel it is a fragment at the depth of the centroid along that pixel's
 * ray). A splat is applied where its centroid lies within the pixel's ray
 * range (clipping planes, view-depth slab, opaque geometry). Isosurfaces
 * inside a splatted cell are not drawn (the splat carries the volume only).
 *
 * Threads: as hov::CellProjector, tiles run in parallel and each
 * pixel is composited by one thread in a fixed order; a cell is binned into
 * every tile its pixel box (or splat footprint) overlaps: the image is
 * bit-identical for any number of threads.
 *
 * Cost (512^2, 2 cores shared, RenderImage, best of 3): the bracket
 * (56071 linear tetrahedra) takes 0.11 s on the fast path, 0.28 s here with
 * no surface (per-segment instead of batched integrals, whole pixel boxes
 * scanned), 0.47 s with one isosurface; the tjunction (quadratic
 * tetrahedra, already per pixel) 1.0 s either way, 1.55 s with a colour array.
 *
 * Thread safety: Render() is not re-entrant.
 * @sa hov::FeatureTile, hov::FeatureSegment, hov::CellProjector
 */
#ifndef hovFeatureProjector_h
#define hovFeatureProjector_h

#include "hovFeatureSegment.h"  // LinearField, FrameData
#include "hovGeneralCellTile.h" // FrameData
#include "hovTileSkeleton.h"    // the tile skeleton, settings, statistics

#include "hovSplat.h" // SplatFootprint

#include <array>  // pixel boxes
#include <memory> // per-thread tiles
#include <vector> // per-frame arrays

namespace hov
{
class CellSetup;
}
namespace hov
{
class ViewRays;
}
namespace hov
{
class FeatureTile;
}
namespace hov
{
struct Features;
}
namespace hov
{
class FeatureProjector
{
public:
  using Box = CellBox;
  using Settings = ProjectorSettings;
  using Statistics = ProjectorStatistics;

  /// A splatted cell.
  struct Splat
  {
    hov::SplatFootprint Footprint;
    glm::dvec3 Center; ///< centroid (dataset coordinates)
  };

  /// What every tile of a frame reads.
  struct Frame
  {
    const hov::CellSetup* Setup = nullptr;
    const std::vector<vtkIdType>* Order = nullptr; ///< ordered cell -> rendered cell
    const hov::ViewRays* Rays = nullptr;
    const float* Depth = nullptr;
    const ProjectorSettings* Settings = nullptr;
    std::vector<Box> Boxes;     ///< per ordered cell
    std::vector<int> SplatOf;   ///< per ordered cell: index into Splats, or -1
    std::vector<Splat> Splats;
    TileBins Bins; ///< the ordered cells per tile
    hov::GeneralCellTile::FrameData General;
    hov::FeatureSegment::FrameData Segment;
    double WitnessTol = 0.0;
    glm::dvec3 PerturbX{ 1.0, 0.0, 0.0 }, PerturbY{ 0.0, 1.0, 0.0 };
  };

  FeatureProjector();
  ~FeatureProjector();

  /**
   * Render as hov::CellProjector::Render with @p features (per-point
   * colour/isosurface fields indexed like the setup's points).
   */
  Statistics Render(const hov::CellSetup& setup,
    const std::vector<vtkIdType>& frontToBack, const hov::ViewRays& rays,
    const hov::TransferFunction& tf, const Settings& settings,
    const hov::Features& features, const float* depth, std::vector<double>& rgba);

  /// Cells splatted in the last frame.
  vtkIdType GetNumberOfSplats() const { return static_cast<vtkIdType>(this->F.Splats.size()); }

private:
  void PrepareCells(const hov::CellSetup& setup, const hov::ViewRays& rays,
    const hov::TransferFunction& tf, const hov::Features& features, hov::EmissionModel emission);

  Frame F;
  ProjectedPoints Points;
  std::vector<hov::FeatureSegment::LinearField> TetColor, TetIso;
  struct TileStore;
  std::unique_ptr<TileStore> Tiles;
};
}

#endif
