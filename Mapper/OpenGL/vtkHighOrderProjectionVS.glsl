//VTK::System::Dec
// Vertex shader of vtkHighOrderProjectionRenderer: region vertices of the
// OpenGL cell projection (HIAC section 7) arrive in clip coordinates (front
// point of the ray segment), with the segment length L, the average
// extinction tau_avg, the colour and the vertex opacity (method M0). Default
// (perspective-correct) interpolation: the attributes are linear on the
// front face.
in vec4 vertexClip;
in vec2 lengthTau;
in vec4 colorAlpha;
out vec2 lengthTauVS;
out vec4 colorAlphaVS;
void main()
{
  gl_Position = vertexClip;
  lengthTauVS = lengthTau;
  colorAlphaVS = colorAlpha;
}
