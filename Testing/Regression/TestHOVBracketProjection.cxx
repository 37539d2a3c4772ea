// The bracket, OPENGL_PROJECTION (colour method M3), VTK-unstructured opacity.
// Data: bracket_tet4_ccx.vtu (DATA{} in CMakeLists.txt);
// baseline ../Data/Baseline/TestHOVBracketProjection.png.
#include "hovRegression.h"

#include "vtkHighOrderVolumeMapper.h" // render-mode and semantics constants

int TestHOVBracketProjection(int argc, char* argv[])
{
  hovRegression::Scene scene;
  scene.Name = "TestHOVBracketProjection";
  scene.Array = "von_mises";
  scene.RenderMode = vtkHighOrderVolumeMapper::OPENGL_PROJECTION;
  scene.Semantics = vtkHighOrderVolumeMapper::VTK_UNSTRUCTURED;
  return hovRegression::Run(argc, argv, scene);
}
