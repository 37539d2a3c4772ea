// The bracket, CPU_ACCURATE, cut open by two clipping planes (x > 40% and a slanted plane).
// Data: bracket_tet4_ccx.vtu (DATA{} in CMakeLists.txt);
// baseline ../Data/Baseline/TestHOVBracketClipping.png.
#include "hovRegression.h"

#include "vtkHighOrderVolumeMapper.h" // render-mode and semantics constants

int TestHOVBracketClipping(int argc, char* argv[])
{
  hovRegression::Scene scene;
  scene.Name = "TestHOVBracketClipping";
  scene.Array = "von_mises";
  scene.RenderMode = vtkHighOrderVolumeMapper::CPU_ACCURATE;
  scene.ClipPlanes = { 0.4, 0.5, 0.5, 1, 0, 0, 0.5, 0.5, 0.6, 0, -0.3, -1 };
  return hovRegression::Run(argc, argv, scene);
}
