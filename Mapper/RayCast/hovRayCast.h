/**
 * @class   hov::RayCast
 * @brief   CPU ray-cast render path for curved Lagrange cells (issue 6): the
 *          VTK adapter of hov::CurvedRayCaster (Module/Kernels).
 *
 * SetInput() converts a vtkUnstructuredGrid (points, its cells' types,
 * connectivity and the cell-data HigherOrderDegrees array, a point scalar
 * array) into a hov::CurvedMeshInput (hov::RayCastCells: Lagrange
 * cells as they are, linear and quadratic cells converted to Lagrange
 * cells) and builds the caster: per cell its boundary patches and bounding
 * box, one BVH over the cells. Other cells, bad nodes and inverted cells are
 * skipped with one summary message.
 * Render() traces one ray per pixel (hov::ViewRays::TracedPixelRay:
 * OpenGL pixel centres, clipping, an optional opaque depth) with
 * vtkSMPTools::For over rows; each ray's segments are categorized
 * (E / PS / S), split at their located breakpoints and integrated exactly in
 * depth (hovCurvedSegment.h), composited front to back. Output: premultiplied
 * float RGBA, and optionally the per-pixel error estimate (ElVis's
 * "pixel-exact" target is an estimate below 1e-3 per channel).
 *
 * MarkInvisibleCells() flags the cells a composite ray can skip under a
 * table (their whole field hull invisible); Render() then computes no
 * interval in them.
 *
 * Used by vtkHighOrderVolumeMapper's RAY_CAST render mode.
 *
 * Thread safety: SetInput() is not thread safe; Render() runs its own
 * parallel loop and must not be called concurrently with SetInput().
 * @sa hovCurvedRayCaster.h, hov::ViewRays
 */
#ifndef hovRayCast_h
#define hovRayCast_h

#include "hovCurvedRayCaster.h" // the caster
#include "hovCurvedSegment.h"   // CurvedSegmentSettings
#include "hovRayCastCells.h" // grid conversion
#include "hovTileBatches.h"  // progress batches

#include "vtkType.h" // vtkMTimeType

#include <string> // messages
#include <vector> // cell flags

class vtkDataArray;
namespace hov
{
class ViewRays;
}
class vtkUnstructuredGrid;

namespace hov
{
class TransferFunction;
}

namespace hov
{
class RayCast
{
public:
  /**
   * Prepare @p grid with the point scalars @p scalars, or with
   * @p cellScalars one value per cell (component @p component, -1:
   * magnitude; cells converted by hov::RayCastCells). Returns
   * false if no cell is usable; @p message receives a summary of skipped
   * cells or the reason for failure (empty if everything was usable).
   */
  bool SetInput(vtkUnstructuredGrid* grid, vtkDataArray* scalars, int component,
    bool cellScalars, std::string* message);

  /// Conversion counts of the last SetInput() (hov::RayCastCells).
  const hov::RayCastCells& GetConversion() const { return this->Mesh; }

  /// Cells prepared / skipped by the last SetInput() (0 prepared if it failed).
  long long GetNumberOfCells() const { return this->Ready ? this->Caster.GetNumberOfCells() : 0; }
  long long GetNumberOfSkippedCells() const { return this->Caster.GetNumberOfSkippedCells(); }

  /**
   * Trace every pixel of @p rays' viewport into @p rgba (4 floats per pixel,
   * premultiplied, row j = 0 at the bottom) and, if given, @p error (1 float
   * per pixel). @p depth (may be null): the OpenGL window depth per pixel of
   * opaque geometry (1 = nothing). Returns false if SetInput() has not
   * succeeded. If given, @p issues receives the pixels whose quadrature or
   * Newton inversion did not converge (their error estimate says how far)
   * and those whose colour was not finite (drawn transparent, error 1).
   */
  struct Issues
  {
    long long NotConverged = 0;
    long long NotFinite = 0;
    long long Rays = 0;        ///< rays traced (pixels with a non-empty view interval)
    long long Segments = 0;    ///< cell intervals integrated (CurvedRayStats::Segments)
    long long Breakpoints = 0; ///< transfer-function breakpoints located inside them
    bool Aborted = false; ///< @p progress returned true: the rows not traced are zero
  };
  /// @p progress (may be empty): called on the calling thread after each of
  /// about hov::ProgressBatches batches of rows with the fraction done;
  /// returning true stops the render (hovTileBatches.h). With @p blend, the
  /// blend mode's pixel instead (CurvedRayCaster::TraceRayBlend, @p tf the
  /// raw blend table) and the extremum's ErrorBound (scalar units) as error.
  bool Render(const hov::ViewRays& rays, const hov::TransferFunction& tf,
    const hov::CurvedSegmentSettings& settings, float* rgba, float* error, const float* depth,
    Issues* issues = nullptr, const hov::ProgressFunction& progress = {},
    const hov::BlendSettings* blend = nullptr,
    const std::vector<unsigned char>* skipCells = nullptr) const;

  /**
   * One flag per caster cell in @p flags: 1 where the cell's rigorous field
   * hull is invisible under @p tf (hov::CurvedRayCaster::IsCellInvisible;
   * vtkSMPTools over the cells). Returns the number flagged. Pass the flags
   * to Render() (composite rays; the caster ignores them for shaded rays
   * under Wilhelms-Van Gelder; Render() ignores flags not sized to the current caster).
   */
  long long MarkInvisibleCells(const hov::TransferFunction& tf, hov::EmissionModel emission,
    std::vector<unsigned char>& flags) const;

private:
  hov::CurvedRayCaster Caster;
  hov::RayCastCells Mesh;
  bool Ready = false;
};
}

#endif
