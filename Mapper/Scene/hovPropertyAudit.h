/**
 * @class   hov::PropertyAudit
 * @brief   One warning per vtkVolumeProperty feature (and mapper feature) that
 *          the frame's render mode does not honour, once per change.
 *
 * After each frame the facade calls Check() with the frame (settings, mode,
 * selected scalars) and its volume property. The audit lists every feature
 * in use that the mode ignores, each as one sentence naming the feature and
 * the mode, and warns about the sentences that were not in the previous
 * frame's list: a feature warns once when it is switched on (or its value or
 * the mode changes), not every frame, and again if it is switched off and on.
 *
 * InterpolationType is honoured as VTK's unstructured mappers define it (they
 * ignore it: the field is interpolated within every cell; NEAREST is the
 * property's default). What is read (and therefore never listed): the colour (RGB or gray) and
 * scalar-opacity functions and ScalarOpacityUnitDistance of the rendered
 * component (component 0, or VectorComponent with IndependentComponents on),
 * in every mode; Shade, Ambient, Diffuse, Specular, SpecularPower and the
 * gradient-opacity function (with DisableGradientOpacity) of component 0 in
 * CPU_ACCURATE, COMPOSITE blending, where neither isosurfaces nor a separate
 * colour array are set. What is listed (README, "Shading and gradient
 * opacity", feature table): a multi-component
 * array with IndependentComponents off (VTK's dependent components; with them
 * on, VectorMode chooses the magnitude or one component, as documented); component
 * weights other than 1; Shade, gradient opacity or lighting coefficients of
 * components other than the rendered one; gradient-opacity nodes with a
 * midpoint or sharpness other than the defaults; Shade or gradient opacity in
 * RAY_CAST and OPENGL_PROJECTION, or with isosurfaces or a separate colour
 * array; TransferFunctionMode TF_2D; label-map functions; SliceFunction;
 * UseClippedVoxelIntensity. (The property's isosurface values always hold
 * one contour, so they cannot tell whether they were set: they belong to the
 * ISOSURFACE blend mode, which the blend-mode handling reports.)
 *
 * Thread safety: rendering thread only.
 * @sa hov::ShadingFrameSettings, vtkHighOrderVolumeMapper
 */
#ifndef hovPropertyAudit_h
#define hovPropertyAudit_h

#include <string> // the sentences
#include <vector> // the last list

class vtkVolumeProperty;

namespace hov
{
class RenderFrame;

class PropertyAudit
{
public:
  /// The unhonoured features of @p frame (see the class doc).
  static std::vector<std::string> List(const RenderFrame& frame, vtkVolumeProperty* property);

  /// Warn (through @p frame) about the features not listed last time; returns their number.
  int Check(const RenderFrame& frame, vtkVolumeProperty* property);

  /// The features listed by the last Check().
  const std::vector<std::string>& GetLast() const { return this->Last; }

private:
  std::vector<std::string> Last;
};
}

#endif
