// The bracket, RAY_CAST (tolerance 1e-3), VTK-unstructured opacity.
// Data: bracket_tet4_ccx.vtu (DATA{} in CMakeLists.txt);
// baseline ../Data/Baseline/TestHOVBracketRayCast.png.
#include "hovRegression.h"

#include "vtkHighOrderVolumeMapper.h" // render-mode and semantics constants

int TestHOVBracketRayCast(int argc, char* argv[])
{
  hovRegression::Scene scene;
  scene.Name = "TestHOVBracketRayCast";
  scene.Array = "von_mises";
  scene.RenderMode = vtkHighOrderVolumeMapper::RAY_CAST;
  scene.Semantics = vtkHighOrderVolumeMapper::VTK_UNSTRUCTURED;
  scene.Width = 64;
  scene.Height = 64;
  return hovRegression::Run(argc, argv, scene);
}
