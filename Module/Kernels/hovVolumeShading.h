/**
 * @file hovVolumeShading.h
 * @brief Shaded emission of the volume itself (vtkVolumeProperty::Shade with
 * Ambient/Diffuse/Specular/SpecularPower and the renderer's lights) and
 * gradient-modulated extinction, as VTK 9.1's GPU ray caster defines them,
 * with the exact closed-form segment integral where the gradient is
 * constant (linear tetrahedra under directional lights).
 *
 * VTK (vtkVolumeShaderComposer.h: ComputeLightingDeclaration,
 * ComputeColorDeclaration, ShadingSingleInput; COMPOSITE blending only, also
 * ISOSURFACE and SLICE; never MIP/MinIP/average), per sample of scalar s
 * with colour c(s), opacity alpha and gradient g:
 *     rgb = clamp(ka A + kd D c + ks S, 0, 1),  alpha' = alpha GO(|g|)
 * composited as (rgb alpha', alpha'). n = g/|g| (toward increasing s, NOT
 * flipped toward the viewer); where |g| = 0, n = 0: the diffuse and specular
 * terms vanish (ambient only). With two-sided lighting (vtkRenderer's
 * default) n.l and n.h are taken in absolute value. D = sum_i I_i Ld_i
 * |n.l_i|, S = sum_i I_i Ls_i |n.h_i|^p (vtkLight colours times intensity,
 * Blinn half vector h = (l + v)/|l + v|, v = toward the eye = -ray
 * direction). A depends on VTK's "light complexity": ONE headlight of
 * intensity 1 (vtkRenderer's automatic light; l = v) uses A = c; any other
 * set of lights uses A = sum_i I_i La_i (the lights' ambient colours,
 * default black). Two VTK quirks are NOT reproduced: with several lights only the last light's specular
 * term survives (`specular =` instead of `+=`), and positional lights use the
 * half vector of -l and v.
 *
 * Here the shaded chromaticity is an affine map of the unshaded one, per
 * channel (ShadingTransform, computed with hovShading.h's ShadePhong, which
 * implements the same Blinn-Phong terms, attenuation and spot cones):
 *     c_sh = clamp(M c + K, 0, 1),   M = ka' + kd D,  K = ks S + ka'' A_L
 * (AmbientTerm::MaterialColor: ka' = ka, ka'' = 0; LightAmbient: ka' = 0,
 * ka'' = ka, A_L = the summed ambient light colour). Shade off: the identity
 * (M = 1, K = 0, no clamp; vtkVolumeProperty: "turning shading off is
 * generally the same as ambient = 1, diffuse = 0, specular = 0").
 * The zero-gradient test is |g| <= GradientFloor (default 0, exactly VTK's
 * `normalLength > 0.0`; TetraGradient returns exactly 0 for a constant field).
 *
 * Exact integral (IntegrateLinearScalarShaded): on a segment where s is
 * linear and M, K and gamma are constant (a linear tetrahedron: constant
 * gradient; directional lights: constant l, and v is constant along a ray),
 * the chromaticity stays piecewise linear in t: M c(s(t)) + K is linear on
 * each transfer-function interval, and the clamp adds at most 6 kinks per
 * interval (where a channel crosses 0 or 1), found by one division each.
 * On every piece extinction gamma tau and c_sh are linear in t, so
 * IntegrateSegment (hovSegmentIntegral.h) is exact on it; pieces are
 * composited front to back with CompositeBehind. Extinction tau(s) is the
 * table's (any OpacitySemantics); gamma = 0 makes the medium transparent
 * even where tau = +inf (0 x opaque = 0 as in VTK's alpha GO); Wilhelms-Van
 * Gelder emission is EmissionFactor c_sh (gamma scales extinction only).
 * With the identity transform and gamma = 1 the result is bitwise
 * IntegrateLinearScalar.
 *
 * Domain: finite sFront, sBack, length > 0 (else transparent), M, K finite,
 * gamma >= 0 finite (NaN or negative -> 0, +inf -> opaque medium). Positional
 * lights make l vary along the ray even on a tetrahedron: use
 * IntegrateShadedPolynomial (hovShadedSegment.h) for them.
 *
 * Thread safety: stateless, re-entrant; the table is read only.
 * @sa hovShading.h, hovGradientOpacity.h, hovShadedSegment.h, hovRayIntegrator.h
 */
#ifndef hovVolumeShading_h
#define hovVolumeShading_h

#include "hovCompositing.h"
#include "hovConfig.h"
#include "hovRayIntegrator.h" // IntegrationSettings
#include "hovShading.h"       // ShadingLight, ShadingMaterial, ShadePhong

namespace hov
{
class TransferFunction;

/// Which ambient term the shaded colour uses (see file doc).
enum class AmbientTerm
{
  MaterialColor = 0, ///< ka c (VTK's single headlight of intensity 1; vtkVolumeProperty's documented invariant)
  LightAmbient = 1   ///< ka sum_i I_i La_i (VTK's GPU shader with any other light set)
};

/// Everything shading needs besides the gradient, the point and the view vector.
struct VolumeShadingSettings
{
  bool Shade = false;       ///< vtkVolumeProperty::GetShade() and COMPOSITE blending
  ShadingMaterial Material; ///< ka, kd, ks, p, two-sided lighting, clamp
  AmbientTerm Ambient = AmbientTerm::MaterialColor;
  double AmbientLight[3] = { 0.0, 0.0, 0.0 }; ///< sum_i I_i La_i (LightAmbient only)
  const ShadingLight* Lights = nullptr;      ///< in the caller's frame (directions, positions)
  int LightCount = 0;
  double GradientFloor = 0.0; ///< |g| <= this: no normal (ambient only)
};

/// c_sh = Clamp ? clamp(Scale c + Offset, 0, 1) : Scale c + Offset, per channel.
struct ShadingTransform
{
  double Scale[3] = { 1.0, 1.0, 1.0 };
  double Offset[3] = { 0.0, 0.0, 0.0 };
  bool Clamp = false;
  bool Lit = false; ///< the normal was defined (|g| > GradientFloor) and Shade on
};

/// True if @p shade is the identity (no effect on any colour).
HOV_EXPORT bool IsIdentity(const ShadingTransform& shade);

/// True if no light is positional: the transform is then constant along a ray for a constant gradient.
HOV_EXPORT bool LightsAreDirectional(const VolumeShadingSettings& settings);

/// Unit normal g/|g| (toward increasing s) or 0 if |g| <= @p floor or not finite
/// (@p normal must not be @p gradient).
HOV_EXPORT bool VolumeNormal(const double gradient[3], double floor, double normal[3]);

/**
 * The affine colour map at @p point (needed by positional lights only) with
 * field gradient @p gradient, seen along the unit vector @p toViewer.
 */
HOV_EXPORT ShadingTransform ComputeShadingTransform(const VolumeShadingSettings& settings,
  const double gradient[3], const double point[3], const double toViewer[3]);

/**
 * ComputeShadingTransform's work that does not depend on the gradient, done
 * once for directional lights and one view vector (along a ray: the lights'
 * unit vectors and half vectors, the two compositions' materials). Holds
 * pointers into the settings, which must outlive it.
 */
struct DirectionalShading
{
  static constexpr int MaxLights = 8;
  const VolumeShadingSettings* Settings = nullptr;
  ShadingMaterial Diffuse, Specular; ///< the two compositions' materials
  int Count = 0;                     ///< lights that reach (in the settings' order)
  LightVectors Lights[MaxLights];
  const double* Colors[MaxLights] = {};
};

/**
 * Fills @p out for @p settings seen along @p toViewer; false (use
 * ComputeShadingTransform per point) if a light is positional or there are
 * more than DirectionalShading::MaxLights.
 */
HOV_EXPORT bool PrepareDirectionalShading(
  const VolumeShadingSettings& settings, const double toViewer[3], DirectionalShading& out);

/// ComputeShadingTransform(settings, @p gradient, any point, toViewer) bit
/// for bit, from @p prepared.
HOV_EXPORT ShadingTransform ComputeShadingTransform(
  const DirectionalShading& prepared, const double gradient[3]);

/// Apply @p shade to the chromaticity @p color (3 channels, in place).
HOV_EXPORT void ApplyShading(const ShadingTransform& shade, double color[3]);

/**
 * Premultiplied RGBA of a segment of length @p length on which s goes
 * linearly from @p sFront to @p sBack, with the constant colour map
 * @p shade and extinction factor @p gamma (file doc). @p pieces, if given,
 * receives the number of linear pieces integrated.
 */
HOV_EXPORT RGBA IntegrateLinearScalarShaded(const TransferFunction& tf, double sFront,
  double sBack, double length, const ShadingTransform& shade, double gamma,
  const IntegrationSettings& settings, int* pieces = nullptr);
}

#endif
