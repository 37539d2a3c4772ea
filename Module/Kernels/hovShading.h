/**
 * @file hovShading.h
 * @brief Shading of an isosurface hit: surface normal from the field
 * gradient, Blinn-Phong lighting with vtkVolumeProperty's coefficients and
 * vtkLight-like lights, and the edge-on opacity of HIAC section 5.2.
 *
 * All vectors are in one frame chosen by the caller (world or camera
 * coordinates), consistently for the point, the normal, the view vector and
 * the lights.
 *
 * Normal (SurfaceNormal): n = g/|g| for the field gradient g, flipped so that
 * n . v >= 0 (v = unit vector from the surface point toward the eye): the
 * surface is lit on the side the viewer sees. Fallback when |g| is zero,
 * subnormal-small or not finite: n = v (the surface is treated as facing the
 * viewer: normal incidence, base opacity, head-on shading); the function
 * returns false so that callers can count such hits.
 *
 * Edge-on opacity (EdgeOnOpacity, HIAC 5.2: "more opaque when it is seen
 * edge-on, as if it were a finite thickness of partially absorbing glass"):
 * a layer of thickness d with opacity alpha at normal incidence has optical
 * depth -ln(1 - alpha); a ray at angle theta to the normal travels d/|cos|
 * through it, so
 *     alphaEdge = 1 - (1 - alpha)^(1 / max(|cos theta|, MinCosine))
 * evaluated as -expm1(log1p(-alpha) / c) (no cancellation for small alpha:
 * alphaEdge ~ alpha / c). Properties: alphaEdge(alpha, 1) = alpha (to 1 ulp),
 * alpha = 0 -> 0, alpha = 1 -> 1 for every angle, increasing in alpha and in
 * 1/|cos|. The cap MinCosine (default 1/100, i.e. at most 100 times the
 * normal-incidence optical depth, reached beyond 89.4 degrees) keeps grazing
 * views finite: a real layer's path is bounded by its curvature, and without
 * a cap a ray tangent to the surface would make it opaque. Input clamped:
 * alpha to [0, 1] (NaN -> 0), |cos| to [MinCosine, 1] (NaN -> 1),
 * MinCosine to [1e-6, 1].
 *
 * Lighting (ShadePhong), per colour channel, surface colour c, material
 * coefficients ka, kd, ks, power p (vtkVolumeProperty::Ambient, Diffuse,
 * Specular, SpecularPower; defaults 0.1, 0.7, 0.2, 10 as there):
 *     C = ka c + sum_lights f_i I_i [ kd max(n.l_i, 0) c Ld_i
 *                                     + ks max(n.h_i, 0)^p Ls_i ]
 * l_i = unit vector toward the light, h_i = (l_i + v)/|l_i + v| (Blinn's half
 * vector, as vtkOpenGLGPUVolumeRayCastMapper's shader), I_i = intensity,
 * Ld_i = Ls_i = the light's colour. Two-sided lighting (vtkRenderer's default,
 * used by the GPU shader): n.l and n.h are taken in absolute value. f_i is 1
 * for directional lights; for positional lights 1/(a0 + a1 d + a2 d^2)
 * (vtkLight attenuation values, d = distance to the light) times the spot
 * factor (cos to the axis)^Exponent inside a cone of ConeAngle < 90 degrees,
 * 0 outside it (ConeAngle >= 90: no cone, as vtkLight). The specular term is
 * not multiplied by c (white highlights, as in VTK). Ambient: ka c, so that
 * ka = 1, kd = ks = 0 is exactly the unshaded colour (what vtkVolumeProperty
 * documents for Shade off); VTK 9.1's GPU shader uses ka c for the headlight
 * only and ka * (sum of the lights' ambient colours, default black) otherwise;
 * we keep the documented invariant. Each channel is clamped to [0, 1] as the
 * GPU shader does (ClampColor, default true).
 *
 * Accuracy: direct formulas, a few ulp per operation. Measured (TestShading):
 * EdgeOnOpacity vs a 50-digit 1 - (1 - a)^(1/c): 2.7e-16 relative;
 * ShadePhong vs a long double transcription of the formula above with 1-3
 * random directional/positional/spot lights: 3.8e-15 absolute (powers up to
 * 100 amplify the rounding of n.h); rotation invariance 3.3e-16.
 * Thread safety: stateless, re-entrant.
 * @sa hovIsosurface.h (the hit's premultiplied RGBA)
 */
#ifndef hovShading_h
#define hovShading_h

#include "hovConfig.h"

namespace hov
{
/// A light (vtkLight's lighting parameters; the caller transforms positions).
struct ShadingLight
{
  /// Direction the light travels (vtkLight focal point - position); the cone
  /// axis of a spot light. Need not be unit length; must be non-zero.
  double Direction[3] = { 0.0, 0.0, -1.0 };
  double Position[3] = { 0.0, 0.0, 0.0 }; ///< positional lights only
  double Color[3] = { 1.0, 1.0, 1.0 };    ///< diffuse and specular colour
  double Intensity = 1.0;
  bool Positional = false;
  double Attenuation[3] = { 1.0, 0.0, 0.0 }; ///< constant, linear, quadratic (positional)
  double ConeAngle = 180.0;                  ///< degrees; >= 90: no spot cone
  double Exponent = 1.0;                     ///< spot falloff exponent
};

/// Lighting coefficients as vtkVolumeProperty defines them (its defaults).
struct ShadingMaterial
{
  double Ambient = 0.1;
  double Diffuse = 0.7;
  double Specular = 0.2;
  double SpecularPower = 10.0;
  bool TwoSidedLighting = true; ///< vtkRenderer's default
  bool ClampColor = true;       ///< clamp each channel to [0, 1] (the GPU shader does)
};

/// Default cap of the edge-on path factor: 1/|cos| <= 100.
constexpr double DefaultEdgeOnMinCosine = 0.01;

/**
 * Unit normal from the field gradient @p gradient, oriented toward the unit
 * view vector @p toViewer (n . v >= 0). Returns false (and @p normal = v) if
 * the gradient is zero, too small to normalise or not finite.
 */
HOV_EXPORT bool SurfaceNormal(const double gradient[3], const double toViewer[3], double normal[3]);

/// Edge-on opacity of a surface of normal-incidence opacity @p alpha seen at
/// |cos| = @p cosIncidence (see file doc).
HOV_EXPORT double EdgeOnOpacity(
  double alpha, double cosIncidence, double minCosine = DefaultEdgeOnMinCosine);

/**
 * Blinn-Phong colour (file doc) of a surface of colour @p baseColor at
 * @p point with unit normal @p normal and unit view vector @p toViewer, lit by
 * @p lightCount lights. Not premultiplied.
 */
HOV_EXPORT void ShadePhong(const double baseColor[3], const double point[3],
  const double normal[3], const double toViewer[3], const ShadingLight* lights, int lightCount,
  const ShadingMaterial& material, double out[3]);

/**
 * ShadePhong in two steps, for callers that compose one lighting with
 * several materials or base colours: the per-light sums
 * @p diffuse = sum f_i I_i max(n.l_i, 0) Ld_i and
 * @p specular = sum f_i I_i max(n.h_i, 0)^p Ls_i (@p material supplies only
 * TwoSidedLighting and SpecularPower), then ComposePhong's
 * ka c + kd diffuse c + ks specular, clamped as ClampColor says.
 * ShadePhong is exactly these two calls.
 */
HOV_EXPORT void PhongLightSums(const double point[3], const double normal[3],
  const double toViewer[3], const ShadingLight* lights, int lightCount,
  const ShadingMaterial& material, double diffuse[3], double specular[3]);
HOV_EXPORT void ComposePhong(const double baseColor[3], const ShadingMaterial& material,
  const double diffuse[3], const double specular[3], double out[3]);

/// One light as seen from a point: the unit vector L toward it, the unit half
/// vector H of L and the view vector (HasHalf false where L + v = 0: the light
/// exactly behind the eye ray) and its Factor (intensity x attenuation x spot).
struct LightVectors
{
  double L[3] = { 0.0, 0.0, 0.0 };
  double H[3] = { 0.0, 0.0, 0.0 };
  bool HasHalf = false;
  double Factor = 0.0;
};

/**
 * PhongLightSums per light, in two steps, for callers that reuse a light's
 * vectors (a directional light and one view vector: the same along a ray):
 * ComputeLightVectors (false if the light does not reach @p point; @p point
 * and @p normal matter for positional lights only), then AddPhongLight adds
 * its terms to @p diffuse and @p specular. PhongLightSums is exactly these
 * calls over its lights, in order, from zero sums.
 */
HOV_EXPORT bool ComputeLightVectors(const ShadingLight& light, const double point[3],
  const double normal[3], const double toViewer[3], LightVectors& out);
HOV_EXPORT void AddPhongLight(const LightVectors& light, const double normal[3],
  const double color[3], const ShadingMaterial& material, double diffuse[3], double specular[3]);
}

#endif
