/**
 * @class   vtkHighOrderCellProjector
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
 * so the image is bit-identical for any number of threads.
 *
 * Speed (what keeps a frame fast, see vtkHighOrderProjectorTile): one
 * parallel pass per frame writes a record per cell in processing order (face
 * planes, field, projected vertices, pixel box, transfer-function interval,
 * or for a cell across nodes a hint where each segment's interval search
 * starts), so the tile loop reads memory in order; the cells are binned from
 * a compact array of their pixel boxes; segments are integrated in batches
 * (hov::SegmentBatch, bit-identical to the scalar kernels); per-frame arrays
 * are kept across frames. None of this changes a bit of the image.
 *
 * General cells (hexahedra, wedges, pyramids, voxels, quadratic cells:
 * vtkHighOrderGeneralCells) take their place in the same order; their pixel
 * box comes from their projected corners and their per-pixel work (exact
 * intervals, polynomial restriction, accurate integral) is done by
 * vtkHighOrderGeneralCellTile. With none in the input, the tetrahedra's loop
 * is exactly what it was (Frame::General is null).
 *
 * Clipping (vtkHighOrderViewRays::SetClipPlanes): each pixel ray starts at its
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
 * @sa vtkHighOrderTetraSetup, vtkHighOrderViewRays, hovRayIntegrator.h
 */
#ifndef vtkHighOrderCellProjector_h
#define vtkHighOrderCellProjector_h

#include "hovRayIntegrator.h" // IntegrationSettings

#include "vtkType.h" // vtkIdType

#include <functional> // progress callback
#include <memory> // scratch buffers
#include <vector> // image, order

class vtkHighOrderTetraSetup;
class vtkHighOrderViewRays;
namespace hov
{
class TransferFunction;
}

class vtkHighOrderCellProjector
{
public:
  struct Settings
  {
    hov::IntegrationSettings Integration;
    double TerminationTransmittance = 1e-9;
    int TileSize = 16;
    /// Order each pixel's segments by entry distance instead of trusting the
    /// cell order (exact for any set of non-overlapping cells).
    bool PerPixelSort = false;
    /// If set: called between tile batches with the fraction done; true aborts (vtkHighOrderTileBatches.h).
    std::function<bool(double)> Progress;
  };

  struct Statistics
  {
    vtkIdType WitnessViolations = 0; ///< pixels where the order was wrong
    vtkIdType Segments = 0;          ///< ray-cell segments integrated
    vtkIdType Pieces = 0;            ///< linear pieces integrated (>= Segments)
    bool Aborted = false;            ///< Progress returned true: unrendered tiles are zero
  };

  /**
   * Render the cells listed in @p frontToBack (rendered-cell indices of
   * @p setup: tetrahedra, then general cells) into @p rgba (premultiplied, 4 doubles per pixel,
   * width*height pixels, row j = 0 at the bottom). @p depth, if not null,
   * holds one OpenGL window depth per pixel of opaque geometry already drawn
   * (the segment is clipped there); 1 means nothing.
   */
  Statistics Render(const vtkHighOrderTetraSetup& setup, const std::vector<vtkIdType>& frontToBack,
    const vtkHighOrderViewRays& rays, const hov::TransferFunction& tf, const Settings& settings,
    const float* depth, std::vector<double>& rgba) const;

private:
  struct Buffers; // per-frame arrays kept across frames (see the .cxx)
  mutable std::shared_ptr<Buffers> Scratch;
};

#endif
