// The bracket, CPU_ACCURATE, GPU-compatible opacity (-ln(1-a)/u).
// Data: bracket_tet4_ccx.vtu (DATA{} in CMakeLists.txt);
// baseline ../Data/Baseline/TestHOVBracketCPUGPUSemantics.png.
#include "hovRegression.h"

#include "vtkHighOrderVolumeMapper.h" // render-mode and semantics constants

int TestHOVBracketCPUGPUSemantics(int argc, char* argv[])
{
  hovRegression::Scene scene;
  scene.Name = "TestHOVBracketCPUGPUSemantics";
  scene.Array = "von_mises";
  scene.RenderMode = vtkHighOrderVolumeMapper::CPU_ACCURATE;
  scene.Semantics = vtkHighOrderVolumeMapper::GPU_COMPATIBLE;
  return hovRegression::Run(argc, argv, scene);
}
