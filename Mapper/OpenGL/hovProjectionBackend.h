/**
 * @class   hov::ProjectionBackend
 * @brief   The OPENGL_PROJECTION render mode (HIAC section 7, for
 *          interaction): the homogeneous regions of every projected cell and
 *          transfer-function slab built on the CPU (hov::ProjectionRegions,
 *          Mapper/Regions), drawn with OpenGL into a float target and
 *          composited over the scene (hov::ProjectionRenderer).
 *
 * Per frame: the shared scene set-up (hov::CellScene: cells, transfer
 * function and, with ProjectionOrder EXACT_ORDER, the visibility order; else
 * the centroid order of ProjectionRegions), the opaque scene depth (skipped
 * when the viewport holds none), then the cells in groups, each built while
 * the previous one is drawn; the float image read back into the mapper's
 * image. Isosurfaces, separate fields, splatting and clipping are not applied
 * (one warning). The vertex colours go to OpenGL as floats: a table whose
 * colours exceed float's range is warned about once per build. Interactive
 * frames (RenderFrame::Interactive): the centroid order and a target of one
 * pixel per f x f block, which the blit replicates over the viewport.
 *
 * Thread safety: rendering thread only.
 * @sa hov::ProjectionRegions, hov::ProjectionRenderer, hov::Backend
 */
#ifndef hovProjectionBackend_h
#define hovProjectionBackend_h

#include "hovBackend.h" // the interface

#include "hovProjectionRegions.h"  // CPU regions
#include "hovProjectionRenderer.h" // OpenGL

#include <vector> // buffers

class vtkHighOrderTransferFunction;

namespace hov
{
class CellScene;

class ProjectionBackend : public Backend
{
public:
  explicit ProjectionBackend(CellScene& scene)
    : Scene(scene)
  {
  }
  int Render(RenderFrame& frame, vtkImageData* floatImage) override;
  bool DrawsIntoWindow() const override { return true; }
  void ReleaseGraphicsResources(vtkWindow* win) override;

private:
  /// Cells, transfer function and (exact order) order of a frame; false if
  /// nothing is to be drawn (errors reported).
  bool PrepareFrame(RenderFrame& frame);
  /// One warning when the table's colours exceed float's range.
  void CheckColorRange(const RenderFrame& frame, vtkHighOrderTransferFunction* tf);
  /// The region triangles of BackToFront, group by group, drawn as they come
  /// into a @p width x @p height target (the frame's, or its reduced size).
  bool Draw(RenderFrame& frame, ProjectionRegions::Settings& settings, const float* depth,
    float* pixels, int width, int height);

  CellScene& Scene;
  ProjectionRegions Regions;
  ProjectionRenderer Renderer;
  ProjectionRegions::Statistics Statistics;
  ProjectionRegions::Geometry Geometry;
  std::vector<float> Depth;
  std::vector<vtkIdType> BackToFront;
  std::vector<float> Reduced, ReducedDepth; ///< an interactive frame's target and depth
  double BuildSeconds = 0.0; ///< the frame's CPU set-up and region building
  bool WarnedFeatures = false;
  /// The table build (and emission model) whose colour range was checked.
  int ColorRangeCheckedBuild = -1;
  int ColorRangeCheckedModel = -1;
};
}

#endif
