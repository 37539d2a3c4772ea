// The bracket, OPENGL_PROJECTION (M3), GPU-compatible opacity.
// Data: bracket_tet4_ccx.vtu (DATA{} in CMakeLists.txt);
// baseline ../Data/Baseline/TestHOVBracketProjectionGPUSemantics.png.
#include "hovRegression.h"

#include "vtkHighOrderVolumeMapper.h" // render-mode and semantics constants

int TestHOVBracketProjectionGPUSemantics(int argc, char* argv[])
{
  hovRegression::Scene scene;
  scene.Name = "TestHOVBracketProjectionGPUSemantics";
  scene.Array = "von_mises";
  scene.RenderMode = vtkHighOrderVolumeMapper::OPENGL_PROJECTION;
  scene.Semantics = vtkHighOrderVolumeMapper::GPU_COMPATIBLE;
  return hovRegression::Run(argc, argv, scene);
}
