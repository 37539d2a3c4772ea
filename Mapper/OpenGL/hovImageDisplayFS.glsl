//VTK::System::Dec
//VTK::Output::Dec
// Fragment shader of hov::ImageDisplay: outputs the CPU path's float
// image, premultiplied RGBA, one texel per viewport pixel (texelFetch, no
// filtering). Blending glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA) puts it
// over what is already drawn.
in vec2 texCoord;
uniform sampler2D image;
void main()
{
  // texCoord is (i + 1/2)/W at the centre of viewport pixel i: floor gives i.
  ivec2 texel = ivec2(floor(texCoord * vec2(textureSize(image, 0))));
  gl_FragData[0] = texelFetch(image, texel, 0);
}
