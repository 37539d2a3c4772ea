/**
 * @file    hov::Features.h
 * @brief   What the feature path of the CPU projector reads per frame:
 *          embedded isosurfaces and their shading, the optional colour and
 *          isosurface fields, subpixel splatting (HIAC sections 5.1-5.3).
 *
 * Filled by vtkHighOrderVolumeMapper each frame; read-only during rendering.
 * With none of the features active (Active() false) the mapper uses the
 * tetrahedra's fast projector (hov::CellProjector) unchanged, and the
 * image is bit for bit what it was without this file.
 *
 * Frames: rays, points and fields live in dataset coordinates; shading runs
 * in world coordinates (the frame of vtkLight positions): DataToWorld maps
 * points, NormalToWorld = (DataToWorld^-1)^T maps gradients.
 * @sa hov::FeatureProjector, hovIsosurface.h, hovShading.h, hovSplat.h
 */
#ifndef hovFeatures_h
#define hovFeatures_h

#include "hovGradientOpacity.h" // GradientOpacityFunction
#include "hovIsosurface.h"      // Isosurface
#include "hovShading.h"         // ShadingLight, ShadingMaterial
#include "hovVolumeShading.h"   // VolumeShadingSettings

#include <glm/glm.hpp> // dmat3, dmat4

#include <vector> // surfaces, lights, fields

namespace hov
{
struct Features
{
  /// Isosurfaces in compositing order of equal depth (isovalue index).
  std::vector<hov::Isosurface> Surfaces;
  std::vector<double> IsoValues; ///< Surfaces[i].Value, contiguous for the kernels
  std::vector<hov::ShadingLight> Lights; ///< world coordinates
  hov::ShadingMaterial Material;         ///< unshaded: Ambient 1, Diffuse 0, Specular 0
  double EdgeOnMinCosine = hov::DefaultEdgeOnMinCosine;
  glm::dmat4 DataToWorld{ 1.0 };
  glm::dmat3 NormalToWorld{ 1.0 };

  /// Per point values of the colour field, or null (colour follows the main scalar).
  const std::vector<double>* ColorField = nullptr;
  /// Per point values of the isosurface field, or null (the main scalar).
  const std::vector<double>* IsoField = nullptr;

  bool Splatting = false;
  /// Cells whose projected bounding box is smaller than this (pixels^2)
  /// and whose sides are at most SplatMaxSide pixels are splatted.
  double SplatPixelThreshold = 2.0;
  static constexpr double SplatMaxSide = 3.0;

  /// The volume's own shading (Shade on; its Lights point into VolumeLights,
  /// world coordinates) and gradient opacity: hov::ShadedCellSegment.
  hov::VolumeShadingSettings VolumeShading;
  std::vector<hov::ShadingLight> VolumeLights;
  hov::GradientOpacityFunction GradientOpacity;
  bool UseGradientOpacity = false;

  bool VolumeActive() const { return this->VolumeShading.Shade || this->UseGradientOpacity; }

  bool Active() const
  {
    return !this->Surfaces.empty() || this->ColorField || this->IsoField || this->Splatting ||
      this->VolumeActive();
  }
};
}

#endif
