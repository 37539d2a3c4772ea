/**
 * @class   hov::BlendCheck
 * @brief   The warnings about vtkHighOrderVolumeMapper's blend mode, each
 *          once per change of the setting: a public BlendMode value the
 *          mapper does not support (ADDITIVE 4, ISOSURFACE 5, SLICE 6 or any
 *          other: rendered as composite, named in the warning), and features
 *          a blend mode other than composite does not apply (isosurfaces,
 *          separate colour/isosurface fields, splatting: ignored).
 *
 * Thread safety: rendering thread only.
 * @sa hovBlendModes.h, hov::FrameSettings
 */
#ifndef hovBlendCheck_h
#define hovBlendCheck_h

#include "hovFrameSettings.h" // FrameSettings, FrameMessages
#include "hovRenderFrame.h"   // BlendSettingsOf's frame

namespace hov
{
/// The kernels' blend settings of @p frame: its mode, AverageIPScalarRange and
/// the data scalar range of the selected scalars (component or magnitude).
BlendSettings BlendSettingsOf(const RenderFrame& frame);

class BlendCheck
{
public:
  /// Warn through @p messages about the public value @p publicMode as
  /// converted into @p settings (see the class doc).
  void Check(int publicMode, const FrameSettings& settings, FrameMessages& messages);

private:
  int LastMode = 0;
  bool LastFeatures = false;
};
}

#endif
