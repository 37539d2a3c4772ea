/**
 * @file hovTestBlendScenes.h
 * @brief Shared set-up of the blend-mode tests (TestBlendModeScenes,
 * TestBlendModesGPU): their oblique camera, their transfer function (colour
 * and opacity nodes at different scalars) and the triquadratic hexahedron on
 * [-1,1]^3 carrying a given field.
 */
#ifndef hovTestBlendScenes_h
#define hovTestBlendScenes_h

#include "hovTestScenes.h" // TF

#include <functional> // the field

class vtkCamera;

namespace hovTest
{
/// The blend tests' perspective view of [-1,1]^3.
void BlendCamera(vtkCamera* cam);
/// The blend tests' transfer function (nodes over [-0.2, 1.4]).
void BlendTF(TF& tf);
/// One VTK_TRIQUADRATIC_HEXAHEDRON on [-1,1]^3 with point scalars f at its nodes.
vtkSmartPointer<vtkUnstructuredGrid> TriquadraticHex(
  const std::function<double(double, double, double)>& f);
}

#endif
