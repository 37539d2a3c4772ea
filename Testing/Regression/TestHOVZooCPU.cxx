// The CalculiX zoo (tetrahedra, hexahedra, wedges, pyramids), CPU_ACCURATE.
// Data: zoo_mixed_ccx.vtu (DATA{} in CMakeLists.txt);
// baseline ../Data/Baseline/TestHOVZooCPU.png.
#include "hovRegression.h"

#include "vtkHighOrderVolumeMapper.h" // render-mode and semantics constants

int TestHOVZooCPU(int argc, char* argv[])
{
  hovRegression::Scene scene;
  scene.Name = "TestHOVZooCPU";
  scene.Array = "temperature";
  scene.RenderMode = vtkHighOrderVolumeMapper::CPU_ACCURATE;
  scene.UnitFraction = 0.15;
  return hovRegression::Run(argc, argv, scene);
}
