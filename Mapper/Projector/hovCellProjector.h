/**
 * @class   hov::CellProjector
 * @brief   HIAC cell projection on the CPU: exact per-pixel ray segments through
 *          linear tetrahedra and general cells, composited in visibility order.
 *
 * HIAC section 5.1 (Williams, Max & Stein 1998): cells are taken in visibility
 * order; each is scan converted; for every pixel centre it covers, the exact
 * ray entry and exit are found in dataset space, the scalar along the segment
 * is split at every transfer-function breakpoint and integrated exactly
 * (hov::IntegrateLinearScalar), and the result is composited (hov::Over).
 *
 * Here the order is front to back (the reverse of a back-to-front visibility
 * sort), so a pixel stops once its accumulated transmittance is below
 * TerminationTransmittance (the error this causes is at most that value).
 * Scan conversion is exact: the pixel centres in each cell's projected
 * bounding box (widened by 1e-6 pixel against round-off) are walked and each
 * pixel's ray is clipped against the cell's four face planes; pixels the ray
 * misses contribute nothing.
 *
 * Threads: the image is split into tiles; each cell is binned, in order, into
 * the tiles its box overlaps; tiles run in parallel (vtkSMPTools) and each
 * pixel is composited by exactly one thread in exactly the visibility order,
 * so the image is bit-identical for any number of threads (the tile skeleton
 * it shares with the feature path: hovTileSkeleton.h).
 *
 * Speed (what keeps a frame fast, see hov::ProjectorTile): one
 * parallel pass per frame writes a record per cell in processing order (face
 * planes, field, projected vertices, pixel box, transfer-function interval,
 * or for a cell across nodes a hint where each segment's interval search
 * starts), so the tile loop reads memory in order; the cells are binned from
 * a compact array of their pixel boxes; segments are integrated in batches
 * (hov::SegmentBatch, bit-identical to the scalar kernels); per-frame arrays
 * are kept across frames. Beyond Settings::RecordBudget (about a million
 * cells) each tile builds its own cells' records instead and the mesh-sized
 * per-frame arrays are freed after each frame (hov::CellRecords: memory
 * before speed). None of this changes a bit of the image.
 *
 * General cells (hexahedra, wedges, pyramids, voxels, quadratic cells:
 * hov::GeneralCells) take their place in the same order; their pixel
 * box comes from their projected corners and their per-pixel work (exact
 * intervals, polynomial restriction, accurate integral) is done by
 * hov::GeneralCellTile. With none in the input, the tetrahedra's loop
 * is exactly what it was (Frame::General is null).
 *
 * Clipping (hov::ViewRays::SetClipPlanes): each pixel ray starts at its
 * clipped entry (the ray origin moves there) and stops at its clipped exit;
 * without clip planes nothing changes.
 *
 * HIAC's z-buffer witness: a pixel counts as a violation if a cell composited
 * later enters the ray in front of the farthest exit composited so far there
 * (by more than 1e-9 of the view depth), i.e. the visibility order was wrong
 * at that pixel.
 *
 * Per-pixel ordering (Settings::PerPixelSort): instead of trusting the cell
 * order, each tile collects its pixels' segments, sorts them by entry
 * distance and composites them in that order; exact for any set of
 * non-overlapping cells, convex or not. The cells are then processed by
 * centroid depth along the central ray (sorted once per frame), so that each
 * pixel's segments arrive nearly sorted. The witness then counts pixels where
 * cells overlap (a mesh defect).
 *
 * Thread safety: Render() is not re-entrant.
 * @sa hov::CellSetup, hov::ViewRays, hovRayIntegrator.h
 */
#ifndef hovCellProjector_h
#define hovCellProjector_h

#include "hovGeneralCellTile.h" // FrameData
#include "hovTileSkeleton.h"    // settings, statistics, the tile skeleton

#include "vtkType.h" // vtkIdType

#include <memory> // scratch buffers
#include <vector> // image, order

namespace hov
{
class CellSetup;
class TransferFunction;
class ViewRays;

class CellProjector
{
public:
  using Settings = ProjectorSettings;
  using Statistics = ProjectorStatistics;

  /**
   * Render the cells listed in @p frontToBack (rendered-cell indices of
   * @p setup: tetrahedra, then general cells) into @p rgba (premultiplied, 4 doubles per pixel,
   * width*height pixels, row j = 0 at the bottom). @p depth, if not null,
   * holds one OpenGL window depth per pixel of opaque geometry already drawn
   * (the segment is clipped there); 1 means nothing.
   */
  Statistics Render(const hov::CellSetup& setup, const std::vector<vtkIdType>& frontToBack,
    const hov::ViewRays& rays, const hov::TransferFunction& tf, const Settings& settings,
    const float* depth, std::vector<double>& rgba) const;

private:
  /// Per-pixel mode: @p frontToBack by centroid depth along the central ray.
  const std::vector<vtkIdType>& DepthOrder(const CellSetup& setup,
    const std::vector<vtkIdType>& frontToBack, const ViewRays& rays) const;

  struct Buffers; // per-frame arrays kept across frames (see the .cxx)
  mutable std::shared_ptr<Buffers> Scratch;
};
}

#endif
