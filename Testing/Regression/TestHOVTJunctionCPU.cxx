// The FEniCSx T-junction (10,521 quadratic tetrahedra, curved boundary cells drawn straight),
// CPU_ACCURATE.
// Data: tjunction_tet10_dolfinx.vtu (DATA{} in CMakeLists.txt);
// baseline ../Data/Baseline/TestHOVTJunctionCPU.png.
#include "hovRegression.h"

#include "vtkHighOrderVolumeMapper.h" // render-mode and semantics constants

int TestHOVTJunctionCPU(int argc, char* argv[])
{
  hovRegression::Scene scene;
  scene.Name = "TestHOVTJunctionCPU";
  scene.Array = "speed";
  scene.RenderMode = vtkHighOrderVolumeMapper::CPU_ACCURATE;
  scene.UnitFraction = 0.1;
  return hovRegression::Run(argc, argv, scene);
}
