//VTK::System::Dec
//HOV::Variant::Dec
// Vertex shader of vtkHighOrderProjectionRenderer: region vertices of the
// OpenGL cell projection (HIAC section 7; record of vtkHighOrderProjectionVertex)
// arrive in clip coordinates (front point of the ray segment) with the
// segment quantities (L | mu, tauFront, tauBack | tauBack mu), linear on the
// front face (the default perspective-correct interpolation is exact for
// them), the colour and the vertex opacity (method M0 only: no other variant
// interpolates it).
in vec4 vertexClip;
in vec3 segmentIn;
in vec4 colorAlpha;
out vec3 segmentVS;
out vec3 colorVS;
#if !HOV_TEXTURE_OPACITY
out float alphaVS;
#endif
void main()
{
  gl_Position = vertexClip;
  segmentVS = segmentIn;
  colorVS = colorAlpha.rgb;
#if !HOV_TEXTURE_OPACITY
  alphaVS = colorAlpha.a;
#endif
}
