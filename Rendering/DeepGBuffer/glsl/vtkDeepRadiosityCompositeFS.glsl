//VTK::System::Dec

//=========================================================================
// Standalone composite of deep screen-space radiosity: layer 0's colour
// becomes RADIANCE + L_ind (the G-buffer's float radiance plus the
// outgoing indirect radiance, fallback included). Written with blend
// (ONE, ZERO) on colour and alpha kept; empty pixels are discarded and keep
// the background.
//=========================================================================

in vec2 texCoord;

uniform sampler2DArray deepDistance;
uniform sampler2DArray deepRadiance;
uniform sampler2D deepIndirect;   // (L_ind, confidence) of layer 0

uniform int deepGuardBand; // layer pixels around the frame

//VTK::DeepGBuffer::Common

//VTK::Output::Dec

void main()
{
  ivec2 pixel = deepFrameTexel(texCoord, textureSize(deepDistance, 0).xy, deepGuardBand);
  if (!(texelFetch(deepDistance, ivec3(pixel, 0), 0).r > 0.0))
  {
    discard;
  }
  vec3 radiance = texelFetch(deepRadiance, ivec3(pixel, 0), 0).rgb;
  gl_FragData[0] = vec4(radiance + texelFetch(deepIndirect, pixel, 0).rgb, 1.0);
}
