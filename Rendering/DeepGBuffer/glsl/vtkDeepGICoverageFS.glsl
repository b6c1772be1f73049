//VTK::System::Dec

//=========================================================================
// vtkDeepGIPass layer-1 coverage probe: drawn inside an occlusion query
// with colour and depth writes off, so the query counts the pixels where
// layer 1 of the deep G-buffer holds a surface (distance > 0).
//=========================================================================

in vec2 texCoord;

uniform sampler2DArray deepDistance;

uniform int deepGuardBand; // layer pixels around the frame

//VTK::DeepGBuffer::Common

//VTK::Output::Dec

void main()
{
  ivec2 pixel = deepFrameTexel(texCoord, textureSize(deepDistance, 0).xy, deepGuardBand);
  if (!(texelFetch(deepDistance, ivec3(pixel, 1), 0).r > 0.0))
  {
    discard;
  }
  gl_FragData[0] = vec4(0.0);
}
