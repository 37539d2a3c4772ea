/**
 * @class   vtkHighOrderProjection
 * @brief   State of vtkHighOrderVolumeMapper's OpenGL projection mode
 *          (HIAC section 7): the region builder, the OpenGL renderer and the
 *          per-frame buffers (reused across frames).
 *
 * Thread safety: rendering thread only.
 * @sa vtkHighOrderProjectionRegions, vtkHighOrderProjectionRenderer
 */
#ifndef vtkHighOrderProjection_h
#define vtkHighOrderProjection_h

#include "hovProjectionRegions.h"  // CPU regions
#include "hovProjectionRenderer.h" // OpenGL

#include <vector> // buffers

struct vtkHighOrderProjection
{
  vtkHighOrderProjectionRegions Regions;
  vtkHighOrderProjectionRenderer Renderer;
  vtkHighOrderProjectionRegions::Statistics Statistics;
  vtkHighOrderProjectionRegions::Geometry Geometry;
  std::vector<float> Depth;
  std::vector<vtkIdType> BackToFront;
  bool WarnedFeatures = false;
  /// The table build (and emission model) whose colour range was checked.
  int ColorRangeCheckedBuild = -1;
  int ColorRangeCheckedModel = -1;
};

#endif
