/**
 * @file    hovShadingSetup.h
 * @brief   The renderer's lights and the volume property's shading and
 *          gradient opacity as the kernels take them (hovShading.h,
 *          hovVolumeShading.h, hovGradientOpacity.h), read once per frame by
 *          the facade into hov::FrameSettings::Shading.
 *
 * Lights: with a renderer, its switched-on vtkLights in world coordinates
 * (GetTransformedPosition / GetTransformedFocalPoint: headlights and camera
 * lights follow the camera), diffuse colour, intensity, positional and spot
 * parameters, the renderer's two-sided lighting. Without one (RenderImage):
 * one white directional headlight along the camera's direction of projection.
 * The ambient term follows VTK's GPU shader (hovVolumeShading.h): one
 * switched-on headlight of intensity 1 (vtkRenderer's automatic light, and
 * RenderImage's) uses ka c; any other set of lights uses ka sum I La.
 *
 * Volume shading: Shade, Ambient, Diffuse, Specular, SpecularPower of
 * component 0, in COMPOSITE blending only (VTK shades no MIP/MinIP/average).
 * Gradient opacity: the nodes (x, value) of component 0's function when
 * vtkVolumeProperty::HasGradientOpacity() and not DisableGradientOpacity, in
 * COMPOSITE blending only (midpoint and sharpness are not read:
 * hov::PropertyAudit warns about them).
 *
 * Thread safety: rendering thread only.
 * @sa hov::FrameSettings, hov::PropertyAudit
 */
#ifndef hovShadingSetup_h
#define hovShadingSetup_h

#include "hovFrameSettings.h" // ShadingFrameSettings

#include "vtkIndent.h" // PrintFrameState

#include <ostream> // PrintFrameState
#include <string>  // unhonoured features
#include <vector>  // lights

class vtkCamera;
class vtkHighOrderTransferFunction;
class vtkRenderer;
class vtkVolume;

namespace hov
{
/**
 * The switched-on lights of @p renderer in world coordinates (or, with no
 * renderer, a white headlight along @p camera's direction of projection),
 * whether lighting is two-sided, and whether they are the single automatic
 * headlight of intensity 1 (@p singleHeadlight; see the file doc).
 */
void ReadLights(vtkRenderer* renderer, vtkCamera* camera, std::vector<ShadingLight>& lights,
  bool& twoSided, bool& singleHeadlight, double ambientLight[3]);

/// @p out from @p volume's property, @p renderer's lights and the blend mode
/// (@p composite: COMPOSITE blending); see the file doc.
void ReadVolumeShading(
  vtkVolume* volume, vtkRenderer* renderer, vtkCamera* camera, bool composite, ShadingFrameSettings& out);

/// vtkHighOrderVolumeMapper::PrintSelf's frame state: the last frame's
/// @p shading, the @p unhonoured features (hov::PropertyAudit) and @p tf.
void PrintFrameState(std::ostream& os, vtkIndent indent, const ShadingFrameSettings& shading,
  const std::vector<std::string>& unhonoured, vtkHighOrderTransferFunction* tf);
}

#endif
