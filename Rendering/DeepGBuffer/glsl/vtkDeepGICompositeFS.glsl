//VTK::System::Dec

//=========================================================================
// vtkDeepGIPass composite of layer 0 (paper sections 3.1-3.6):
//   colour = DIRECT + AV * AMBIENT + L_ind + REFLECTIVITY * L_r
// with DIRECT = RADIANCE - AMBIENT, i.e. RADIANCE - (1 - AV) * AMBIENT plus
// the indirect terms; with the multiplying composition (a scene without an
// ambient term, DEEP_GI_AO_MULTIPLY) AV * RADIANCE plus the indirect terms. The effects that did not run this frame are compiled
// out (DEEP_GI_AO, DEEP_GI_RADIOSITY, DEEP_GI_REFLECTIONS below), so their
// terms are exactly 0 (AV = 1). Written with blend (ONE, ZERO) on colour
// and alpha kept; empty pixels are discarded and keep the background.
//=========================================================================

//VTK::DeepGI::Effects

in vec2 texCoord;

uniform sampler2DArray deepDistance;
uniform sampler2DArray deepRadiance;
#if DEEP_GI_AO
#if !DEEP_GI_AO_MULTIPLY
uniform sampler2DArray deepAmbient;
#endif
uniform sampler2D deepVisibility;  // AV in red
#endif
#if DEEP_GI_RADIOSITY
uniform sampler2D deepIndirect;    // L_ind of layer 0 (rgb)
#endif
#if DEEP_GI_REFLECTIONS
uniform sampler2D deepReflected;   // L_r (rgb), a = 1 where traced
uniform sampler2DArray deepReflectivity;
#endif

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
  vec3 colour = texelFetch(deepRadiance, ivec3(pixel, 0), 0).rgb;
#if DEEP_GI_AO
  float av = clamp(texelFetch(deepVisibility, pixel, 0).r, 0.0, 1.0);
#if DEEP_GI_AO_MULTIPLY
  // No ambient term in the scene: VTK's lights stand for all the light
  // arriving, so AV scales the whole direct radiance (like vtkSSAOPass).
  colour *= av;
#else
  colour -= (1.0 - av) * texelFetch(deepAmbient, ivec3(pixel, 0), 0).rgb;
#endif
#endif
#if DEEP_GI_RADIOSITY
  colour += texelFetch(deepIndirect, pixel, 0).rgb;
#endif
#if DEEP_GI_REFLECTIONS
  vec4 reflected = texelFetch(deepReflected, pixel, 0);
  if (reflected.a > 0.0)
  {
    colour += texelFetch(deepReflectivity, ivec3(pixel, 0), 0).rgb * reflected.rgb;
  }
#endif
  gl_FragData[0] = vec4(max(colour, vec3(0.0)), 1.0);
}
