//VTK::System::Dec
//HOV::Variant::Dec
// Vertex shader of hov::ProjectionRenderer: region vertices of the
// OpenGL cell projection (HIAC section 7; record of hov::ProjectionVertex)
// arrive in clip coordinates (front point of the ray segment) with the
// segment quantities (L | mu, tauFront, tauBack | tauBack mu), linear on the
// front face (the default perspective-correct interpolation is exact for
// them), the colour and the vertex opacity (method M0 only: no other variant
// interpolates it). Perspective: the front point relative to the eye, P, is
// recovered from the clip position (clip -> dataset matrix), also linear on
// the front face.
in vec4 vertexClip;
in vec3 segmentIn;
in vec4 colorAlpha;
out vec3 segmentVS;
out vec3 colorVS;
#if !HOV_TEXTURE_OPACITY && !HOV_ANALYTIC_OPACITY
out float alphaVS;
#endif
#if HOV_PERSPECTIVE
uniform mat4 clipToData;
uniform vec3 eye;
out vec3 frontVS;
#endif
void main()
{
  gl_Position = vertexClip;
  segmentVS = segmentIn;
  colorVS = colorAlpha.rgb;
#if !HOV_TEXTURE_OPACITY && !HOV_ANALYTIC_OPACITY
  alphaVS = colorAlpha.a;
#endif
#if HOV_PERSPECTIVE
  vec4 h = clipToData * vertexClip;
  frontVS = h.xyz / h.w - eye;
#endif
}
