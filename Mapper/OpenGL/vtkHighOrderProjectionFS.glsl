//VTK::System::Dec
//VTK::Output::Dec
// Fragment shader of vtkHighOrderProjectionRenderer (HIAC section 7): the
// opacity of the fragment's ray segment from the 2D texture
// M(X, Y) = 1 - exp(-exp(X + Y)), X = ln(L / lengthScale),
// Y = ln(tau_avg lengthScale) (methods M1-M3) or interpolated (M0); output
// premultiplied (k alpha, alpha) (Williams-Max), or (g L phi, alpha) for the
// effective glow g of Wilhelms-Van Gelder emission (hovProjectionColor.h). Fragments behind the opaque
// geometry already drawn (scene depth, one texel per pixel) are discarded.
in vec4 rayVS;
in vec2 tauVS;
in vec4 colorAlphaVS;
uniform sampler2D opacityTable;
uniform sampler2D sceneDepth;
uniform int useDepth;
uniform int perspective;
uniform int textureOpacity;
uniform int premultipliedColor;
uniform float lengthScale;
uniform float logMin;
uniform float logMax;

// Port of hov::OpacityFromTexture (Module/Kernels/hovProjectionColor.cxx):
// same shift of the coordinates along X + Y = const (exact, no clamping),
// same bilinear interpolation between texel centres.
float hovOpacityFromTexture(float len, float tau)
{
  if (!(len > 0.0) || !(tau > 0.0))
  {
    return 0.0;
  }
  float x = log(len / lengthScale);
  float y = log(tau * lengthScale);
  float s = x + y;
  if (s <= 2.0 * logMin)
  {
    return exp(s);
  }
  if (s >= 2.0 * logMax)
  {
    return 1.0;
  }
  x = clamp(x, max(logMin, s - logMax), min(logMax, s - logMin));
  y = s - x;
  int n = textureSize(opacityTable, 0).x;
  float fx = (x - logMin) / (logMax - logMin) * float(n - 1);
  float fy = (y - logMin) / (logMax - logMin) * float(n - 1);
  int i = min(int(fx), n - 2);
  int j = min(int(fy), n - 2);
  float tx = fx - float(i);
  float ty = fy - float(j);
  float a = mix(texelFetch(opacityTable, ivec2(i, j), 0).r, texelFetch(opacityTable, ivec2(i + 1, j), 0).r, tx);
  float b = mix(texelFetch(opacityTable, ivec2(i, j + 1), 0).r, texelFetch(opacityTable, ivec2(i + 1, j + 1), 0).r, tx);
  return mix(a, b, ty);
}

void main()
{
  if (useDepth == 1 && gl_FragCoord.z > texelFetch(sceneDepth, ivec2(gl_FragCoord.xy), 0).r)
  {
    discard;
  }
  // Segment length and average extinction (vtkHighOrderProjectionRegions):
  // parallel projection: interpolated directly; perspective: from the front
  // point P relative to the eye, mu = |P|/|Q|, tauFront and tauBack mu.
  float len = rayVS.x;
  float tauAvg = tauVS.y;
  if (perspective == 1)
  {
    float mu = max(rayVS.w, 1e-30);
    len = length(rayVS.xyz) * max(1.0 - mu, 0.0) / mu;
    tauAvg = 0.5 * (tauVS.x + tauVS.y / mu);
  }
  float alpha = textureOpacity == 1 ? hovOpacityFromTexture(len, tauAvg)
                                    : clamp(colorAlphaVS.a, 0.0, 1.0);
  // Williams-Max: chromaticity k times alpha. Wilhelms-Van Gelder: effective
  // glow g times L phi(D) = L (1 - e^-D)/D, D = L tau_avg (= alpha / tau_avg;
  // its series below D = 1e-3, where alpha / tau_avg loses digits).
  float depth = len * tauAvg;
  float glow = depth > 1e-3 ? alpha / tauAvg : len * (1.0 - 0.5 * depth);
  vec3 rgb = colorAlphaVS.rgb * (premultipliedColor == 1 ? glow : alpha);
  gl_FragData[0] = vec4(rgb, alpha);
}
