//VTK::System::Dec

//=========================================================================
// COMPOSITE_AMBIENT: outputs radiance - (1 - AV) ambient of
// layer 0. COMPOSITE_MULTIPLY: outputs the filtered ambient visibility where layer 0
// has a surface; the pass blends it multiplicatively (dst.rgb *= AV) over
// the resolved layer-0 image. Empty pixels are discarded and keep the
// background.
//=========================================================================

in vec2 texCoord;

uniform sampler2D deepVisibility;
uniform sampler2DArray deepDistance;
uniform sampler2DArray deepRadiance; // DEEP_COMPOSITE_AMBIENT only
uniform sampler2DArray deepAmbient;  // DEEP_COMPOSITE_AMBIENT only
uniform int deepMode;                // DEEP_COMPOSITE_MULTIPLY or DEEP_COMPOSITE_AMBIENT

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
  float av = clamp(texelFetch(deepVisibility, pixel, 0).r, 0.0, 1.0);
  if (deepMode == DEEP_COMPOSITE_AMBIENT)
  {
    // COMPOSITE_AMBIENT: written with blend (ONE, ZERO) on colour, alpha kept.
    vec3 radiance = texelFetch(deepRadiance, ivec3(pixel, 0), 0).rgb;
    vec3 ambient = texelFetch(deepAmbient, ivec3(pixel, 0), 0).rgb;
    gl_FragData[0] = vec4(max(radiance - (1.0 - av) * ambient, vec3(0.0)), 1.0);
    return;
  }
  gl_FragData[0] = vec4(av, av, av, 1.0);
}
