// The CalculiX bracket (56,071 linear tetrahedra), CPU_ACCURATE, VTK-unstructured opacity.
// Data: bracket_tet4_ccx.vtu (DATA{} in CMakeLists.txt);
// baseline ../Data/Baseline/TestHOVBracketCPU.png.
#include "hovRegression.h"

#include "vtkHighOrderVolumeMapper.h" // render-mode and semantics constants

int TestHOVBracketCPU(int argc, char* argv[])
{
  hovRegression::Scene scene;
  scene.Name = "TestHOVBracketCPU";
  scene.Array = "von_mises";
  scene.RenderMode = vtkHighOrderVolumeMapper::CPU_ACCURATE;
  scene.Semantics = vtkHighOrderVolumeMapper::VTK_UNSTRUCTURED;
  return hovRegression::Run(argc, argv, scene);
}
