// vtkHighOrderVolumeMapper: the setters of its real-valued knobs. Like
// vtkSetClampMacro they clamp to the documented range (with a warning naming
// the setter, the value and the range), but a NaN (which vtkSetClampMacro
// lets through: every comparison with it is false) or an infinity is refused
// with an error naming the setter, and the value stays.
#include "vtkHighOrderVolumeMapper.h"

#include <cmath> // std::isfinite

namespace
{
/// Clamps @p value into [lo, hi] into @p field; false (nothing set) if not
/// finite; @p clamped if it was outside.
bool SetFiniteClamped(
  double& field, double value, double lo, double hi, bool& modified, bool& clamped)
{
  modified = clamped = false;
  if (!std::isfinite(value))
  {
    return false;
  }
  const double v = value < lo ? lo : (value > hi ? hi : value);
  clamped = v != value;
  modified = field != v;
  field = v;
  return true;
}
}

#define HOV_FINITE_SETTER(name, lo, hi)                                                          \
  void vtkHighOrderVolumeMapper::Set##name(double value)                                         \
  {                                                                                              \
    bool modified = false, clamped = false;                                                      \
    if (!SetFiniteClamped(this->name, value, lo, hi, modified, clamped))                         \
    {                                                                                            \
      vtkErrorMacro(<< "Set" #name "(" << value << "): not a finite number; keeping "            \
                    << this->name);                                                              \
    }                                                                                            \
    else if (clamped)                                                                            \
    {                                                                                            \
      vtkWarningMacro(<< "Set" #name "(" << value << "): outside [" << lo << ", " << hi          \
                      << "]; clamped to " << this->name);                                        \
    }                                                                                            \
    if (modified)                                                                                \
    {                                                                                            \
      this->Modified();                                                                          \
    }                                                                                            \
  }

// Below 1e-8 the image error bound (2x) is beyond float's resolution, and the
// refined table only grows (1e-12: 10^6 nodes, every one a breakpoint).
HOV_FINITE_SETTER(GPUOpacityTolerance, 1e-8, 0.1)
HOV_FINITE_SETTER(TerminationTransmittance, 0.0, 0.1)
HOV_FINITE_SETTER(SplatPixelThreshold, 0.0, 1e6)
HOV_FINITE_SETTER(RayCastTolerance, 1e-12, 0.1)
HOV_FINITE_SETTER(RayCastInteractiveUpdateRate, 0.0, 1e6)
HOV_FINITE_SETTER(EmissionScale, 0.0, 1e6)
