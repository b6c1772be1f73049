//VTK::System::Dec

//=========================================================================
// Temporal filter and outgoing indirect radiance of deep screen-space
// radiosity (Mara et al. 2016, sections 3.2-3.3), layers 0 and 1 at once.
//   E_t = E (1 - alpha) + reproject(E_t-1) alpha
// where the reprojected surface (its plane extrapolated to the previous
// texel's centre, deepExpectedPreviousDistance) lies within deepTolerance
// (world units, camera depth difference) of either of last frame's layers
// (the nearer one is used), else E_t = E. Outputs:
//   0, 1: the history of layers 0, 1: (E_t, distance), 0 where empty;
//   2, 3: (L, confidence) of layers 0, 1 with the outgoing indirect
//         radiance L = rho boost(rho) E_t / pi (eq. 6), blended with the
//         environment fallback c L + (1 - c) rho E_env / pi when
//         deepFallback is on (c the confidence, section 3.2, Figure 9);
//         E_t extrapolated by deepExtrapolation for a still image.
//=========================================================================

in vec2 texCoord;

uniform sampler2D deepInput0;     // filtered (E, confidence) of layer 0
uniform sampler2D deepInput1;
uniform sampler2D deepHistory0;   // last frame's (E, distance) of layer 0
uniform sampler2D deepHistory1;
uniform sampler2D deepKey;        // both layers' distance and normal (vtkDeepGeometryKeyFS)
uniform sampler2DArray deepAlbedo;
uniform int deepHasHistory;
uniform mat4 deepToPrevious;
uniform mat4 deepPrevProjection;
uniform float deepTolerance;      // world units
uniform float deepAlpha;
uniform float deepExtrapolation;  // rho / (1 - rho), 0: none (ExtrapolateBounces)
uniform int deepBoost;
uniform int deepFallback;
uniform vec3 deepEnvironment;     // environment irradiance E_env
uniform float deepIrradianceLimit;

//VTK::DeepGBuffer::Common

//VTK::DeepScreenSpace::Common

//VTK::Output::Dec

// `geometry`: the layer's (distance, packed normal) from the key.
void filterLayer(ivec2 pixel, vec2 size, int layer, vec2 geometry, out vec4 history,
  out vec4 indirect)
{
  history = vec4(0.0);
  indirect = vec4(0.0);
  float d = geometry.x;
  if (!(d > 0.0))
  {
    return;
  }
  vec4 now = layer == 0 ? texelFetch(deepInput0, pixel, 0) : texelFetch(deepInput1, pixel, 0);
  vec3 E = now.rgb;
  vec4 last = vec4(0.0); // the last frame's (E, distance) at this texel
  if (deepHasHistory != 0 && deepExtrapolation > 0.0)
  {
    last = layer == 0 ? texelFetch(deepHistory0, pixel, 0) : texelFetch(deepHistory1, pixel, 0);
  }
  if (deepHasHistory != 0 && deepAlpha > 0.0)
  {
    vec3 X = deepPositionFromDistance(vec2(pixel) + 0.5, size, d);
    ivec2 texel;
    float expected;
    if (deepLastFrameTexel(pixel, d, X, deepUnpackOct16(geometry.y), deepToPrevious,
          deepPrevProjection, size, texel, expected))
    {
      vec4 h0 = texelFetch(deepHistory0, texel, 0);
      vec4 h1 = texelFetch(deepHistory1, texel, 0);
      float e0 = h0.a > 0.0 ? abs(h0.a - expected) : 1e30;
      float e1 = h1.a > 0.0 ? abs(h1.a - expected) : 1e30;
      if (min(e0, e1) <= deepTolerance)
      {
        E = mix(E, e0 <= e1 ? h0.rgb : h1.rgb, deepAlpha);
      }
    }
  }
  // A float guard, not a physical limit: with rho = 1 and delta = 1 in a
  // closed room the bounces grow without bound (as the true radiosity would),
  // and the clamp keeps them finite.
  E = min(E, vec3(deepIrradianceLimit));
  history = vec4(E, d);
  vec3 rho = texelFetch(deepAlbedo, ivec3(pixel, layer), 0).rgb;
  vec3 shown = deepExtrapolateBounces(E, last, d, deepExtrapolation, deepIrradianceLimit);
  indirect =
    deepOutgoingIndirect(rho, shown, now.a, deepBoost != 0, deepFallback != 0, deepEnvironment,
      deepIrradianceLimit);
}

void main()
{
  vec2 size = vec2(textureSize(deepKey, 0));
  ivec2 pixel = min(ivec2(texCoord * size), ivec2(size) - 1);
  vec4 key = texelFetch(deepKey, pixel, 0);
  vec4 history0, history1, indirect0, indirect1;
  filterLayer(pixel, size, 0, key.xy, history0, indirect0);
  filterLayer(pixel, size, 1, key.zw, history1, indirect1);
  gl_FragData[0] = history0;
  gl_FragData[1] = history1;
  gl_FragData[2] = indirect0;
  gl_FragData[3] = indirect1;
}
