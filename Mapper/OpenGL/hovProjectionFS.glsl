//VTK::System::Dec
//VTK::Output::Dec
//HOV::Variant::Dec
// Fragment shader of hov::ProjectionRenderer (HIAC section 7), one
// variant per combination of the HOV_* switches (no run-time branches): the
// opacity of the fragment's ray segment from the 2D texture
// M(u, v) = 1 - exp(-u v) (methods M1-M3, hovOpacityFromTexture), or
// 1 - exp(-d) computed here (HOV_ANALYTIC_OPACITY), or interpolated (M0);
// output premultiplied (k alpha, alpha) (Williams-Max),
// or (g L phi, alpha) for the effective glow g of Wilhelms-Van Gelder
// emission (HOV_GLOW, hovProjectionColor.h). Fragments behind the opaque
// geometry already drawn fail the depth test (hov::ProjectionRenderer).
in vec3 segmentVS;
in vec3 colorVS;
#if !HOV_TEXTURE_OPACITY && !HOV_ANALYTIC_OPACITY
in float alphaVS;
#endif
#if HOV_PERSPECTIVE
in vec3 frontVS;
#endif
#if HOV_TEXTURE_OPACITY
uniform sampler2D opacityTable;
uniform float opacityScale;  // (Size - 1) / (UMax Size)
uniform float opacityOffset; // 1 / (2 Size): the centre of the first texel
uniform float opacityLast;   // (Size - 1/2) / Size: the centre of the last texel

// Port of hov::OpacityFromTexture (Module/Kernels/hovProjectionColor.cxx):
// M(u, v) = 1 - exp(-u v) at u = v = sqrt(d), d = L tau_avg (exact, since M
// depends on u v only), bilinear by the texture unit (GL_LINEAR); beyond
// UMax the last texel, 1.
float hovOpacityFromTexture(float d)
{
  float t = min(sqrt(d) * opacityScale + opacityOffset, opacityLast);
  return texture(opacityTable, vec2(t, t)).r;
}
#endif

#if HOV_GPU_OPACITY
uniform float inverseUnit; // 1 / unit distance

// GPU-compatible semantics: the mean of -ln(1 - a) over the segment, a linear
// from aF to aB, unit distance 1. Port of hov::GPUAverageExtinction
// (Module/Kernels/hovProjectionColor.cxx): -ln(1 - min a) + M(x),
// M(x) = sum x^n / (n (n+1)) (series below x = 0.1) = 1 + (1-x) ln(1-x) / x,
// x = (max a - min a) / (1 - min a); 1 - a clamped at 1e-12. An opaque
// medium (a = 1 over the whole transfer-function interval) arrives as the
// marker a = 2 (hov::ProjectionVertex): a huge extinction.
float hovGPUAverageExtinction(float aF, float aB)
{
  if (min(aF, aB) >= 1.5)
  {
    return 1e30;
  }
  // (Both ends at 1 without the marker: a segment at the node where a reaches
  // 1, rounded; the clamp below gives -ln(1e-12), as the tables do.)
  float lo = clamp(min(aF, aB), 0.0, 1.0), hi = clamp(max(aF, aB), 0.0, 1.0);
  float big = max(1.0 - lo, 1e-12), small = max(1.0 - hi, 1e-12);
  float x = min((hi - lo) / big, 1.0);
  float m;
  if (x < 0.1)
  {
    m = x * (0.5 + x * (1.0 / 6.0 + x * (1.0 / 12.0 + x * (1.0 / 20.0 + x * (1.0 / 30.0)))));
  }
  else
  {
    float ratio = small / big;
    m = 1.0 + ratio * log(ratio) / x;
  }
  // ln(1 - lo): by its series below lo = 0.05 (GLSL's log is only accurate
  // to 2^-21 absolute near 1, useless for small opacities), else log(big).
  float lnBig = lo < 0.05
    ? -lo * (1.0 + lo * (1.0 / 2.0 + lo * (1.0 / 3.0 + lo * (1.0 / 4.0 + lo * (1.0 / 5.0 + lo * (1.0 / 6.0))))))
    : log(big);
  return m - lnBig;
}
#endif

void main()
{
  // Segment length and average extinction (hov::ProjectionVertex).
#if HOV_PERSPECTIVE
  float inverseMu = 1.0 / max(segmentVS.x, 1e-30);
  float len = length(frontVS) * max(inverseMu - 1.0, 0.0);
  float backValue = segmentVS.z * inverseMu;
#else
  float len = segmentVS.x;
  float backValue = segmentVS.z;
#endif
#if HOV_GPU_OPACITY
  // The ends carry opacities (GPU-compatible semantics; hov::ProjectionVertex).
  float tauAvg = hovGPUAverageExtinction(segmentVS.y, backValue) * inverseUnit;
#else
  float tauAvg = 0.5 * (segmentVS.y + backValue);
#endif
  float depth = max(len, 0.0) * max(tauAvg, 0.0);
#if HOV_TEXTURE_OPACITY
  float alpha = hovOpacityFromTexture(depth);
#elif HOV_ANALYTIC_OPACITY
  // vtkHighOrderVolumeMapper::OPACITY_ANALYTIC: 1 - exp(-d), by its series
  // below d = 1e-3 (1 - exp(-d) in float is a multiple of 6e-8 there: faint
  // volumes, alpha ~ 1e-7, were off by up to 400%).
  float alpha = depth < 1e-3 ? depth * (1.0 - depth * (0.5 - depth * (1.0 / 6.0)))
                             : 1.0 - exp(-depth);
#else
  float alpha = clamp(alphaVS, 0.0, 1.0);
#endif
#if HOV_GLOW
  // Effective glow g times L phi(D) = L (1 - e^-D)/D, D = L tau_avg (= alpha
  // / tau_avg; its series below D = 1e-3, where alpha / tau_avg loses digits).
  float glow = depth > 1e-3 ? alpha / tauAvg : len * (1.0 - 0.5 * depth);
  gl_FragData[0] = vec4(colorVS * glow, alpha);
#else
  gl_FragData[0] = vec4(colorVS * alpha, alpha);
#endif
}
