/**
 * @class   hov::RayCastShading
 * @brief   The volume's own shading and gradient opacity for RAY_CAST: the
 *          frame's hov::ShadingFrameSettings as the curved ray caster takes
 *          them (CurvedSegmentSettings::Shading / GradientOpacity,
 *          hovCurvedShadedSegment.h).
 *
 * The rays of RAY_CAST are in dataset coordinates: the lights (world
 * coordinates) are brought there by the inverse volume matrix (positions by
 * M^-1, directions by the inverse of its 3x3 part), so that n.l, n.h and the
 * gradient magnitude are those of the world for a rigid volume matrix (a
 * scaled one shades and reads the gradient-opacity function in dataset
 * units). The gradient-opacity function is rebuilt, and its messages
 * reported, only when its nodes change.
 *
 * Thread safety: rendering thread only (the settings it fills are read by
 * every ray thread).
 * @sa hov::RayCastBackend, hovShadingSetup.h
 */
#ifndef hovRayCastShading_h
#define hovRayCastShading_h

#include "hovGradientOpacity.h" // the function
#include "hovVolumeShading.h"   // VolumeShadingSettings

#include <vector> // lights, nodes

namespace hov
{
class RenderFrame;
struct CurvedSegmentSettings;

class RayCastShading
{
public:
  /// Point @p settings at this frame's shading and gradient opacity (or at none).
  void Prepare(const RenderFrame& frame, CurvedSegmentSettings& settings);

private:
  VolumeShadingSettings Shading;
  std::vector<ShadingLight> Lights; ///< dataset coordinates
  GradientOpacityFunction GradientOpacity;
  std::vector<OpacityNode> Nodes; ///< what GradientOpacity was built from
  bool Built = false;
};
}

#endif
