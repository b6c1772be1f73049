//VTK::System::Dec

//=========================================================================
// Draws one quantity of one deep G-buffer layer into the renderer's
// framebuffer, with that layer's hardware depth, so that VTK's translucent,
// volume and overlay steps composite against it. Empty pixels are discarded
// and keep the renderer's background.
//=========================================================================

in vec2 texCoord;

uniform sampler2DArray deepQuantityTexture; // the displayed quantity's layers
uniform sampler2DArray deepDistance;
uniform sampler2DArray deepHardwareDepth;
uniform int deepLayer;
uniform int deepQuantity; // vtkDeepGBufferPass::Quantity
uniform vec2 deepDistanceRange;
uniform int deepGuardBand; // pixels of the layers around the frame

//VTK::DeepGBuffer::Common

//VTK::Output::Dec

void main()
{
  ivec3 texel = ivec3(deepFrameTexel(texCoord, textureSize(deepDistance, 0).xy, deepGuardBand),
    deepLayer);
  float distance = texelFetch(deepDistance, texel, 0).r;
  if (distance <= 0.0)
  {
    discard;
  }
  vec4 value = texelFetch(deepQuantityTexture, texel, 0);
  vec4 color;
  if (deepQuantity == DEEP_QUANTITY_RADIANCE)
  {
    color = value;
  }
  else if (deepQuantity == DEEP_QUANTITY_NORMAL)
  {
    color = vec4(deepDecodeOct16(value.rg) * 0.5 + 0.5, 1.0);
  }
  else if (deepQuantity == DEEP_QUANTITY_DEPTH)
  {
    float t = (distance - deepDistanceRange.x) / max(deepDistanceRange.y - deepDistanceRange.x, 1e-30);
    color = vec4(vec3(clamp(t, 0.0, 1.0)), 1.0);
  }
  else // ALBEDO, AMBIENT, REFLECTIVITY
  {
    color = vec4(value.rgb, 1.0);
  }
  gl_FragData[0] = color;
  gl_FragDepth = texelFetch(deepHardwareDepth, texel, 0).r;
}
