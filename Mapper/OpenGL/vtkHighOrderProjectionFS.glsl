//VTK::System::Dec
//VTK::Output::Dec
//HOV::Variant::Dec
// Fragment shader of vtkHighOrderProjectionRenderer (HIAC section 7), one
// variant per combination of the HOV_* switches (no run-time branches): the
// opacity of the fragment's ray segment from the 2D texture
// M(X, Y) = 1 - exp(-exp(X + Y)) (methods M1-M3, hovOpacityFromTexture) or
// interpolated (M0); output premultiplied (k alpha, alpha) (Williams-Max),
// or (g L phi, alpha) for the effective glow g of Wilhelms-Van Gelder
// emission (HOV_GLOW, hovProjectionColor.h). HOV_DEPTH: fragments behind the
// opaque geometry already drawn (scene depth, one texel per pixel) are
// discarded.
in vec3 segmentVS;
in vec4 colorAlphaVS;
#if HOV_PERSPECTIVE
in vec3 frontVS;
#endif
#if HOV_DEPTH
uniform sampler2D sceneDepth;
#endif
#if HOV_TEXTURE_OPACITY
uniform sampler2D opacityTable;
uniform float logMin;
uniform float logMax;

// Port of hov::OpacityFromTexture (Module/Kernels/hovProjectionColor.cxx),
// same steps in float: the optical depth d = L tau_avg gives s = ln d = X + Y;
// below 2 logMin the opacity is d, above 2 logMax 1; else Y is the texel row
// nearest s/2, X = s - Y (exact: M depends on X + Y only) and the opacity is
// the linear interpolation along that row.
float hovOpacityFromTexture(float d)
{
  int n = textureSize(opacityTable, 0).x;
  float step = (logMax - logMin) / float(n - 1);
  float s = clamp(log(max(d, 1e-37)), 2.0 * logMin, 2.0 * logMax);
  int j = clamp(int(floor((0.5 * s - logMin) / step + 0.5)), 0, n - 1);
  float fx = clamp((s - (logMin + float(j) * step) - logMin) / step, 0.0, float(n - 1));
  int i = min(int(fx), n - 2);
  float a = texelFetch(opacityTable, ivec2(i, j), 0).r;
  float b = texelFetch(opacityTable, ivec2(i + 1, j), 0).r;
  float m = mix(a, b, fx - float(i));
  m = s <= 2.0 * logMin ? d : m;
  return d > 0.0 ? m : 0.0;
}
#endif

void main()
{
#if HOV_DEPTH
  if (gl_FragCoord.z > texelFetch(sceneDepth, ivec2(gl_FragCoord.xy), 0).r)
  {
    discard;
  }
#endif
  // Segment length and average extinction (vtkHighOrderProjectionVertex).
#if HOV_PERSPECTIVE
  float mu = max(segmentVS.x, 1e-30);
  float len = length(frontVS) * max(1.0 - mu, 0.0) / mu;
  float tauAvg = 0.5 * (segmentVS.y + segmentVS.z / mu);
#else
  float len = segmentVS.x;
  float tauAvg = 0.5 * (segmentVS.y + segmentVS.z);
#endif
  float depth = max(len, 0.0) * max(tauAvg, 0.0);
#if HOV_TEXTURE_OPACITY
  float alpha = hovOpacityFromTexture(depth);
#else
  float alpha = clamp(colorAlphaVS.a, 0.0, 1.0);
#endif
#if HOV_GLOW
  // Effective glow g times L phi(D) = L (1 - e^-D)/D, D = L tau_avg (= alpha
  // / tau_avg; its series below D = 1e-3, where alpha / tau_avg loses digits).
  float glow = depth > 1e-3 ? alpha / tauAvg : len * (1.0 - 0.5 * depth);
  gl_FragData[0] = vec4(colorAlphaVS.rgb * glow, alpha);
#else
  gl_FragData[0] = vec4(colorAlphaVS.rgb * alpha, alpha);
#endif
}
