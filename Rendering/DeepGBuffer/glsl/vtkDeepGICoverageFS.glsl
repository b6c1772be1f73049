//VTK::System::Dec

//=========================================================================
// vtkDeepGIPass layer-1 coverage probe: drawn inside an occlusion query
// with colour and depth writes off, so the query counts the pixels where
// layer 1 of the deep G-buffer holds a surface (distance > 0).
//=========================================================================

in vec2 texCoord;

uniform sampler2DArray deepDistance;

//VTK::Output::Dec

void main()
{
  ivec2 size = textureSize(deepDistance, 0).xy;
  ivec2 pixel = min(ivec2(texCoord * vec2(size)), size - 1);
  if (!(texelFetch(deepDistance, ivec3(pixel, 1), 0).r > 0.0))
  {
    discard;
  }
  gl_FragData[0] = vec4(0.0);
}
