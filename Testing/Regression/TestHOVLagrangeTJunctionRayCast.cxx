// The FEniCSx T-junction on 3,790 order-4 Lagrange tetrahedra (curved), RAY_CAST,
// clipped at z < 0.
// Data: tjunction_lagrange_tet_p4.vtu (DATA{} in CMakeLists.txt);
// baseline ../Data/Baseline/TestHOVLagrangeTJunctionRayCast.png.
#include "hovRegression.h"

#include "vtkHighOrderVolumeMapper.h" // render-mode and semantics constants

int TestHOVLagrangeTJunctionRayCast(int argc, char* argv[])
{
  hovRegression::Scene scene;
  scene.Name = "TestHOVLagrangeTJunctionRayCast";
  scene.Array = "speed";
  scene.RenderMode = vtkHighOrderVolumeMapper::RAY_CAST;
  scene.Width = 64;
  scene.Height = 40;
  scene.ClipPlanes = { 0.5, 0.5, 0.5, 0, 0, -1 };
  scene.UnitFraction = 0.1;
  scene.Zoom = 2.2;
  return hovRegression::Run(argc, argv, scene);
}
