// The T-junction (quadratic tetrahedra, curved), RAY_CAST (tolerance 1e-2: the slowest test at 1e-3).
// Data: tjunction_tet10_dolfinx.vtu (DATA{} in CMakeLists.txt); baseline ../Data/Baseline/TestHOVTJunctionRayCast.png.
#include "hovRegression.h"

#include "vtkHighOrderVolumeMapper.h"

int TestHOVTJunctionRayCast(int argc, char* argv[])
{
  hovRegression::Scene scene;
  scene.Name = "TestHOVTJunctionRayCast";
  scene.Array = "speed";
  scene.RenderMode = vtkHighOrderVolumeMapper::RAY_CAST;
  scene.Width = 48;
  scene.Height = 32;
  scene.UnitFraction = 0.1;
  scene.Zoom = 2.2;
  scene.RayCastTolerance = 1e-2;
  return hovRegression::Run(argc, argv, scene);
}
