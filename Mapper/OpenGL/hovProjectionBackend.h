/**
 * @class   hov::ProjectionState
 * @brief   State of vtkHighOrderVolumeMapper's OpenGL projection mode
 *          (HIAC section 7): the region builder, the OpenGL renderer and the
 *          per-frame buffers (reused across frames).
 *
 * Thread safety: rendering thread only.
 * @sa hov::ProjectionRegions, hov::ProjectionRenderer
 */
#ifndef hovProjection_h
#define hovProjection_h

#include "hovProjectionRegions.h"  // CPU regions
#include "hovProjectionRenderer.h" // OpenGL

#include <vector> // buffers

namespace hov
{
struct ProjectionState
{
  hov::ProjectionRegions Regions;
  hov::ProjectionRenderer Renderer;
  hov::ProjectionRegions::Statistics Statistics;
  hov::ProjectionRegions::Geometry Geometry;
  std::vector<float> Depth;
  std::vector<vtkIdType> BackToFront;
  bool WarnedFeatures = false;
  /// The table build (and emission model) whose colour range was checked.
  int ColorRangeCheckedBuild = -1;
  int ColorRangeCheckedModel = -1;
};
}

#endif
