//VTK::System::Dec

//=========================================================================
// Standalone composite of vtkDeepReflectionPass: where a ray was traced,
// layer 0's colour becomes RADIANCE + REFLECTIVITY * L_r (floats); other
// pixels are discarded and keep the resolved G-buffer image.
//=========================================================================

in vec2 texCoord;

uniform sampler2D deepReflected; // rgb L_r, a = 1 where traced
uniform sampler2DArray deepRadiance;
uniform sampler2DArray deepReflectivity;

uniform int deepGuardBand; // layer pixels around the frame

//VTK::DeepGBuffer::Common

//VTK::Output::Dec

void main()
{
  ivec2 pixel = deepFrameTexel(texCoord, textureSize(deepReflected, 0), deepGuardBand);
  vec4 reflected = texelFetch(deepReflected, pixel, 0);
  if (reflected.a <= 0.0)
  {
    discard;
  }
  vec3 radiance = texelFetch(deepRadiance, ivec3(pixel, 0), 0).rgb;
  vec3 reflectivity = texelFetch(deepReflectivity, ivec3(pixel, 0), 0).rgb;
  gl_FragData[0] = vec4(radiance + reflectivity * reflected.rgb, 1.0);
}
