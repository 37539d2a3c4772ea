/**
 * @file    hovRobustnessCase.h
 * @brief   One random, mostly malformed, rendering case for hovRobustness
 *          (issue 21): a small grid of random cell types (tetrahedra,
 *          hexahedra, voxels, wedges, pyramids, quadratic and Lagrange cells,
 *          2D and unsupported cells, broken connectivity), points and scalars
 *          with NaN/Inf/huge/denormal values, degenerate and inverted cells,
 *          an absurd transfer function now and then, a camera that may define
 *          no view, and random mapper settings in every render mode.
 *
 * A case is a pure function of its seed, so a failure is reproduced with
 * `hovRobustness --case <seed>`. The description lists what was drawn.
 */
#ifndef hovRobustnessCase_h
#define hovRobustnessCase_h

#include "vtkCamera.h"
#include "vtkHighOrderVolumeMapper.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cstdint> // seeds
#include <string>  // description

namespace hovRobustness
{
/// Everything one case renders.
struct Case
{
  std::uint64_t Seed = 0;
  vtkSmartPointer<vtkUnstructuredGrid> Grid;
  vtkNew<vtkHighOrderVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkVolumeProperty> Property;
  vtkNew<vtkCamera> Camera;
  int Width = 16, Height = 16;
  bool InWindow = false; ///< render in the shared window instead of RenderImage
  std::string Description;
};

/// Builds case @p seed into @p c (a fresh Case).
void Build(std::uint64_t seed, Case& c);
}

#endif
