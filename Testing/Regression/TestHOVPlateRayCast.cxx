// The FEniCSx plate with a hole (192 order-4 Lagrange hexahedra, curved), RAY_CAST, GPU-compatible
// opacity.
// Data: platehole_lagrange_hex_q4.vtu (DATA{} in CMakeLists.txt);
// baseline ../Data/Baseline/TestHOVPlateRayCast.png.
#include "hovRegression.h"

#include "vtkHighOrderVolumeMapper.h" // render-mode and semantics constants

int TestHOVPlateRayCast(int argc, char* argv[])
{
  hovRegression::Scene scene;
  scene.Name = "TestHOVPlateRayCast";
  scene.Array = "von_mises";
  scene.RenderMode = vtkHighOrderVolumeMapper::RAY_CAST;
  scene.Semantics = vtkHighOrderVolumeMapper::GPU_COMPATIBLE;
  scene.UnitFraction = 0.01;
  scene.Width = 64;
  scene.Height = 64;
  return hovRegression::Run(argc, argv, scene);
}
