// The T-junction, CPU_ACCURATE, two shaded isosurfaces of the speed, cut open by a clipping plane
// (z < 0).
// Data: tjunction_tet10_dolfinx.vtu (DATA{} in CMakeLists.txt);
// baseline ../Data/Baseline/TestHOVTJunctionIsosurfaces.png.
#include "hovRegression.h"

#include "vtkHighOrderVolumeMapper.h" // render-mode and semantics constants

int TestHOVTJunctionIsosurfaces(int argc, char* argv[])
{
  hovRegression::Scene scene;
  scene.Name = "TestHOVTJunctionIsosurfaces";
  scene.Array = "speed";
  scene.RenderMode = vtkHighOrderVolumeMapper::CPU_ACCURATE;
  scene.Isosurfaces = { 0.25, 0.2, 0.5, 1.0, 0.6, 0.6, 1.0, 0.6, 0.1, 0.9 };
  scene.ClipPlanes = { 0.5, 0.5, 0.5, 0, 0, -1 };
  scene.UnitFraction = 0.1;
  return hovRegression::Run(argc, argv, scene);
}
