// The zoo (mixed linear cells), RAY_CAST.
// Data: zoo_mixed_ccx.vtu (DATA{} in CMakeLists.txt);
// baseline ../Data/Baseline/TestHOVZooRayCast.png.
#include "hovRegression.h"

#include "vtkHighOrderVolumeMapper.h" // render-mode and semantics constants

int TestHOVZooRayCast(int argc, char* argv[])
{
  hovRegression::Scene scene;
  scene.Name = "TestHOVZooRayCast";
  scene.Array = "temperature";
  scene.RenderMode = vtkHighOrderVolumeMapper::RAY_CAST;
  scene.Width = 64;
  scene.Height = 48;
  scene.UnitFraction = 0.15;
  return hovRegression::Run(argc, argv, scene);
}
