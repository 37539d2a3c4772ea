//VTK::System::Dec
// Vertex shader of vtkHighOrderProjectionRenderer: region vertices of the
// OpenGL cell projection (HIAC section 7) arrive in clip coordinates (front
// point of the ray segment) with the ray and extinction quantities of
// vtkHighOrderProjectionRegions (linear on the front face, so the default
// perspective-correct interpolation is exact for them), the colour and the
// vertex opacity (method M0).
in vec4 vertexClip;
in vec4 rayIn;
in vec2 tauIn;
in vec4 colorAlpha;
out vec4 rayVS;
out vec2 tauVS;
out vec4 colorAlphaVS;
void main()
{
  gl_Position = vertexClip;
  rayVS = rayIn;
  tauVS = tauIn;
  colorAlphaVS = colorAlpha;
}
