/**
 * @file    hovViewCheck.h
 * @brief   Whether a camera (and a volume's matrix) define a usable view, and
 *          if not, why: the one check every render mode and entry point of
 *          vtkHighOrderVolumeMapper applies before it renders.
 *
 * A view is usable when the camera's position, focal point, view-up vector,
 * view angle (perspective) or parallel scale (parallel), clipping range and
 * the volume's matrix are finite; the position differs from the focal point;
 * the view-up vector is not parallel to the direction of projection; the
 * parallel scale is positive; the clipping range has near < far (and near > 0
 * in perspective); and the composite data-to-clip matrix is invertible. VTK
 * itself accepts most of these and then produces NaN matrices, so without this
 * check the modes failed differently (an error with status 1, an error with
 * status 0, or a blank window with no message).
 */
#ifndef hovViewCheck_h
#define hovViewCheck_h

#include <string> // the reason

class vtkCamera;
class vtkMatrix4x4;

namespace hov
{
/**
 * Empty if @p camera and @p volumeMatrix (may be null: identity) give a
 * usable view at aspect ratio @p aspect; else a sentence saying what is wrong
 * (no trailing period).
 */
std::string CheckView(vtkCamera* camera, vtkMatrix4x4* volumeMatrix, double aspect);
}

#endif
