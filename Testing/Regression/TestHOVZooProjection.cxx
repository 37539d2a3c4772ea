// The zoo (mixed linear cells), OPENGL_PROJECTION (M3).
// Data: zoo_mixed_ccx.vtu (DATA{} in CMakeLists.txt);
// baseline ../Data/Baseline/TestHOVZooProjection.png.
#include "hovRegression.h"

#include "vtkHighOrderVolumeMapper.h" // render-mode and semantics constants

int TestHOVZooProjection(int argc, char* argv[])
{
  hovRegression::Scene scene;
  scene.Name = "TestHOVZooProjection";
  scene.Array = "temperature";
  scene.RenderMode = vtkHighOrderVolumeMapper::OPENGL_PROJECTION;
  scene.UnitFraction = 0.15;
  return hovRegression::Run(argc, argv, scene);
}
