/**
 * @class   hov::ProjectorBackend
 * @brief   The CPU_ACCURATE render mode: HIAC's cell projection on the CPU
 *          (sections 4-6), exact per-pixel ray segments composited in
 *          visibility order, with the features of sections 5.1-5.3 when one
 *          is set.
 *
 * Per frame: the shared scene set-up (hov::CellScene: cells, transfer
 * function, visibility order), the pixel rays with their clipping, then
 * hov::CellProjector (the plain path) or, with isosurfaces, separate fields
 * or splatting, hov::FeatureProjector (the feature path, prepared by
 * hov::FeatureSetup). A cyclic visibility order is composited per pixel. The
 * image is the frame's double RGBA. Blend modes other than composite:
 * hov::BlendProjector (no order, no features).
 *
 * Interactive frames (RenderFrame::Subsampling f > 1): the same exact rays,
 * one per f x f block of pixels, replicated onto the block (hovReducedImage.h).
 *
 * Also the image of RenderImage() in OPENGL_PROJECTION mode (no window).
 *
 * Thread safety: rendering thread only (the projectors run vtkSMPTools).
 * @sa hov::CellProjector, hov::FeatureProjector, hov::Backend
 */
#ifndef hovProjectorBackend_h
#define hovProjectorBackend_h

#include "hovBackend.h" // the interface

#include "hovBlendProjector.h" // the blend modes
#include "hovCellProjector.h" // the plain path
#include "hovFeatureSetup.h"  // the feature path

#include <vector> // interactive frames

namespace hov
{
class CellScene;

class ProjectorBackend : public Backend
{
public:
  explicit ProjectorBackend(CellScene& scene)
    : Scene(scene)
  {
  }
  int Render(RenderFrame& frame, vtkImageData* floatImage) override;

private:
  /// The feature settings of @p frame: -1 error (reported), 0 none active, 1 active.
  int PrepareFeatures(const RenderFrame& frame);

  CellScene& Scene;
  CellProjector Projector;
  BlendProjector Blend;
  FeatureSetup Features;
  std::vector<double> Reduced; ///< the reduced image of an interactive frame
  std::vector<float> Depth;    ///< its opaque depth
};
}

#endif
