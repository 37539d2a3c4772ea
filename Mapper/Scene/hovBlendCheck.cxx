#include "hovBlendCheck.h"

#include "vtkDataArray.h" // the scalar range

#include <string> // messages

namespace
{
/// vtkVolumeMapper's name of blend mode @p mode.
std::string BlendModeName(int mode)
{
  switch (mode)
  {
    case 4:
      return "ADDITIVE_BLEND (4)";
    case 5:
      return "ISOSURFACE_BLEND (5)";
    case 6:
      return "SLICE_BLEND (6)";
    default:
      return "value " + std::to_string(mode);
  }
}
}

void hov::BlendCheck::Check(int publicMode, const FrameSettings& s, FrameMessages& messages)
{
  const bool supported = publicMode >= 0 && publicMode <= 3;
  if (!supported && publicMode != this->LastMode)
  {
    messages.Warning("Blend mode " + BlendModeName(publicMode) +
      " is not supported (COMPOSITE, MAXIMUM_INTENSITY, MINIMUM_INTENSITY and "
      "AVERAGE_INTENSITY are); rendered as COMPOSITE_BLEND.");
  }
  const bool features = s.Blend != BlendMode::Composite &&
    (s.NumberOfIsosurfaces() > 0 || !s.ColorArray.empty() || !s.IsosurfaceArray.empty() ||
      s.Splatting);
  if (features && (publicMode != this->LastMode || !this->LastFeatures))
  {
    messages.Warning("Isosurfaces, separate colour/isosurface fields and splatting are not "
                     "applied with a blend mode other than COMPOSITE_BLEND; they are ignored.");
  }
  this->LastMode = publicMode;
  this->LastFeatures = features;
}

hov::BlendSettings hov::BlendSettingsOf(const RenderFrame& frame)
{
  BlendSettings b;
  b.Mode = frame.Settings.Blend;
  b.AverageRange[0] = frame.Settings.AverageRange[0];
  b.AverageRange[1] = frame.Settings.AverageRange[1];
  if (frame.Scalars.Array)
  {
    // vtkDataArray::GetRange(-1): the range of the magnitude.
    frame.Scalars.Array->GetRange(b.ScalarRange, frame.Scalars.Component);
  }
  return b;
}
