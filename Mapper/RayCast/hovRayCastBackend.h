/**
 * @struct  hov::RayCastState
 * @brief   Internal: what vtkHighOrderVolumeMapper keeps between RAY_CAST
 *          frames (Mapper/vtkHighOrderVolumeMapperRayCast.cxx): the prepared
 *          caster, the cache keys that decide when to rebuild it, its own
 *          transfer-function table and the error image.
 *
 * Thread safety: used by one mapper on the rendering thread.
 * @sa hov::RayCast, vtkHighOrderVolumeMapper
 */
#ifndef hovRayCastState_h
#define hovRayCastState_h

#include "hovRayCast.h"          // the caster adapter
#include "vtkHighOrderTransferFunction.h" // its table

#include "vtkImageData.h" // the error image
#include "vtkNew.h"

#include <vector> // buffers

class vtkDataArray;

namespace hov
{
struct RayCastState
{
  hov::RayCast Caster;
  bool Valid = false;
  vtkMTimeType InputTime = 0;
  vtkDataArray* Array = nullptr;
  vtkMTimeType ArrayTime = 0;
  int Component = -2;
  bool FeatureWarned = false;

  vtkNew<vtkHighOrderTransferFunction> TransferFunction;
  vtkNew<vtkImageData> ErrorImage;
  std::vector<float> RGBA, Error, Depth;
  /// Wall seconds per traced ray of the last frame (0: none yet), for the
  /// interactive frame's time budget.
  double SecondsPerRay = 0.0;
};
}

#endif
