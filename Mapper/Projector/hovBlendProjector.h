/**
 * @class   hov::BlendProjector
 * @brief   The blend modes MAXIMUM_INTENSITY, MINIMUM_INTENSITY and
 *          AVERAGE_INTENSITY of CPU_ACCURATE (and of OPENGL_PROJECTION, which
 *          shows this image): per pixel, a hov::RayBlendState accumulated over
 *          all the pixel's ray segments, resolved into the pixel by
 *          hov::ResolveBlend (hovBlendModes.h).
 *
 * No visibility order is needed (max, min and sums commute): the cells are
 * binned into tiles by their pixel boxes (the CPU projector's tile skeleton,
 * hovTileSkeleton.h) in any order, and each pixel's state is accumulated by
 * one thread. Per pixel and cell:
 *  - linear tetrahedra: the ray clipped exactly against the four face planes
 *    (the composite path's clip, hov::tile::ClipRayFaces); the field is
 *    affine along the segment, so its end values give the extremum exactly
 *    and hov::AccumulateLinearSegment the average;
 *  - general cells (hexahedra, wedges, pyramids, quadratic cells): the exact
 *    ray/cell intervals and the field's polynomial pieces with their error
 *    bound (hov::GeneralCellTile::Collect / Restrict: the composite path's),
 *    each accumulated by hov::AccumulatePolynomialSegment.
 * The pixel's error bound (the extremum's ErrorBound: 0 on linear cells, the
 * restriction and root-bracket bound otherwise) goes into @p error if given.
 * Rays are the composite path's (clipping planes, view-depth slab, opaque
 * depth).
 *
 * Thread safety: Render() is not re-entrant (vtkSMPTools inside).
 * @sa hovBlendModes.h, hov::CellProjector, hov::GeneralCellTile
 */
#ifndef hovBlendProjector_h
#define hovBlendProjector_h

#include "hovTileSkeleton.h" // settings, statistics, tiles

#include "hovBlendModes.h" // BlendSettings

#include <memory> // per-frame buffers
#include <vector> // image

namespace hov
{
class CellSetup;
class TransferFunction;

class BlendProjector
{
public:
  /**
   * The blend image of every rendered cell of @p setup into @p rgba
   * (premultiplied, 4 doubles per pixel, row 0 at the bottom) with the raw
   * table @p table (BlendModeTableSpec); @p error (may be null): one bound
   * per pixel. Tile size and progress from @p settings.
   */
  ProjectorStatistics Render(const CellSetup& setup, const ViewRays& rays,
    const TransferFunction& table, const BlendSettings& blend, const ProjectorSettings& settings,
    const float* depth, std::vector<double>& rgba, std::vector<double>* error = nullptr) const;

private:
  struct Buffers; // per-frame arrays and per-thread tiles (see the .cxx)
  mutable std::shared_ptr<Buffers> Scratch;
};
}

#endif
