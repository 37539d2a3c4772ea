//VTK::System::Dec
//VTK::Output::Dec
//HOV::Variant::Dec
// Fragment shader of vtkHighOrderProjectionRenderer (HIAC section 7), one
// variant per combination of the HOV_* switches (no run-time branches): the
// opacity of the fragment's ray segment from the 2D texture
// M(u, v) = 1 - exp(-u v) (methods M1-M3, hovOpacityFromTexture), or
// 1 - exp(-d) computed here (HOV_ANALYTIC_OPACITY), or interpolated (M0);
// output premultiplied (k alpha, alpha) (Williams-Max),
// or (g L phi, alpha) for the effective glow g of Wilhelms-Van Gelder
// emission (HOV_GLOW, hovProjectionColor.h). Fragments behind the opaque
// geometry already drawn fail the depth test (vtkHighOrderProjectionRenderer).
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

void main()
{
  // Segment length and average extinction (vtkHighOrderProjectionVertex).
#if HOV_PERSPECTIVE
  float inverseMu = 1.0 / max(segmentVS.x, 1e-30);
  float len = length(frontVS) * max(inverseMu - 1.0, 0.0);
  float tauAvg = 0.5 * (segmentVS.y + segmentVS.z * inverseMu);
#else
  float len = segmentVS.x;
  float tauAvg = 0.5 * (segmentVS.y + segmentVS.z);
#endif
  float depth = max(len, 0.0) * max(tauAvg, 0.0);
#if HOV_TEXTURE_OPACITY
  float alpha = hovOpacityFromTexture(depth);
#elif HOV_ANALYTIC_OPACITY
  float alpha = 1.0 - exp(-depth); // vtkHighOrderVolumeMapper::OPACITY_ANALYTIC
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
