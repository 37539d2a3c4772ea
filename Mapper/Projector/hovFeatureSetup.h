/**
 * @class   hov::FeatureSetup
 * @brief   The mapper's side of the feature path: turns the mapper settings,
 *          the input's arrays, the renderer's lights and the volume property
 *          into hov::Features, and owns the feature projector.
 *
 * Arrays: the colour and isosurface arrays are point arrays of the input,
 * selected by name; a component (>= 0) or the magnitude (-1) as for the main
 * scalars. Missing, non-numeric or too short arrays are errors (nothing is
 * drawn); a component out of range is clamped with a warning; NaN/Inf values
 * are replaced by 0 with a warning. Arrays are re-read only when the input,
 * the array or the selection changes.
 *
 * Lights (Phong shading of isosurfaces, hov::ShadePhong): with a renderer,
 * its switched-on vtkLights in world coordinates (GetTransformedPosition /
 * GetTransformedFocalPoint: headlights and camera lights follow the camera),
 * diffuse colour, intensity, positional/spot parameters, the renderer's
 * two-sided lighting. Without one (RenderImage): a white directional
 * headlight along the camera's direction of projection. Material:
 * vtkVolumeProperty's Ambient, Diffuse, Specular, SpecularPower of
 * component 0 when its Shade is on; with Shade off the surfaces are
 * unshaded (their colour as given: ambient 1, diffuse 0, specular 0), as
 * vtkVolumeProperty documents for its volume shading. Edge-on opacity
 * (HIAC 5.2) applies in both cases.
 *
 * Thread safety: not thread safe (called once per frame by the mapper).
 * @sa hov::Features, hov::FeatureProjector
 */
#ifndef hovFeatureSetup_h
#define hovFeatureSetup_h

#include "hovFeatureProjector.h" // the renderer
#include "hovFeatures.h"         // the frame settings
#include "hovFrameSettings.h"    // ShadingFrameSettings

#include "vtkType.h" // vtkMTimeType

#include <string> // errors, names
#include <vector> // surfaces, values

class vtkCamera;
class vtkDataArray;
class vtkRenderer;
class vtkUnstructuredGridBase;
class vtkVolume;

namespace hov
{
class FeatureSetup
{
public:
  struct Options
  {
    std::vector<hov::Isosurface> Surfaces;
    std::string ColorArray; ///< empty: colour from the main scalars
    int ColorComponent = -1;
    std::string IsoArray; ///< empty: isosurfaces of the main scalars
    int IsoComponent = -1;
    bool Splatting = false;
    double SplatPixelThreshold = 2.0;
    /// The volume's shading and gradient opacity (null: none).
    const hov::ShadingFrameSettings* Shading = nullptr;
  };

  /**
   * Fill GetFeatures() for a frame. Returns false with @p error set if an
   * array is unusable; @p warnings receives non-fatal messages.
   */
  bool Prepare(const Options& options, vtkUnstructuredGridBase* input, vtkRenderer* renderer,
    vtkCamera* camera, vtkVolume* volume, std::string& error, std::vector<std::string>& warnings);

  const hov::Features& GetFeatures() const { return this->Features; }
  hov::FeatureProjector& GetProjector() { return this->Projector; }

private:
  struct FieldCache
  {
    std::vector<double> Values;
    vtkDataArray* Array = nullptr;
    vtkMTimeType ArrayTime = 0;
    vtkMTimeType InputTime = 0;
    int Component = -2;
  };
  bool PrepareField(const std::string& name, int component, const char* what,
    vtkUnstructuredGridBase* input, FieldCache& cache, std::string& error,
    std::vector<std::string>& warnings);
  void PrepareLights(vtkRenderer* renderer, vtkCamera* camera, vtkVolume* volume);
  /// The volume's shading and gradient opacity into the features.
  void PrepareVolumeShading(const hov::ShadingFrameSettings* shading, std::vector<std::string>& warnings);

  hov::Features Features;
  FieldCache Color, Iso;
  std::vector<hov::OpacityNode> GradientOpacityNodes; ///< what Features.GradientOpacity was built from
  hov::FeatureProjector Projector;
};
}

#endif
