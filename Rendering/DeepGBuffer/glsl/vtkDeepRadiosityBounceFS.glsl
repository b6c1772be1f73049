//VTK::System::Dec

//=========================================================================
// Input radiosity B of deep screen-space radiosity (Mara et al. 2016,
// sections 3.2-3.3, Table 1's "previous bounce radiosity"), for layers 0
// and 1 at once:
//   B(Y) = direct(Y) + delta * L_ind,t-1(Y)
// direct = RADIANCE - AMBIENT of the layer (VTK's outgoing radiance from
// its lights), L_ind,t-1 = rho boost(rho) E_t-1 / pi (eq. 6) from last
// frame's final irradiance E_t-1, reverse-reprojected to Y and taken from
// whichever previous layer lies within deepTolerance (world units, camera
// depth difference) of the reprojected surface (its plane extrapolated to
// the previous texel's centre, deepExpectedPreviousDistance, with the
// plane's own normal, deepGeometricNormal); 0 where neither does or there is
// no history (the first frame gives the single bounce). The history may be
// on a reduced grid (vtkDeepRadiosityPass::SetResolutionDivisor):
// deepPrevProjection and deepHistorySize are the grid's, so the
// reprojection lands on its texels, and at a still camera texel s reads grid
// texel floor(s / D + 1 / 2), whose receiver leaves s out of its gather
// (vtkDeepRadiosityFS).
// B is written only where the gather reads it: the gather's taps use MIP
// levels deepSourceLevel (Table 2's minimum MIP level) and coarser, whose
// rotated-grid texels are all level-0 texels that level deepSourceLevel
// holds (section 3.4). Output texel q is B of the level-0 texel stored at
// texel q of that level, so the bounce costs 4^-deepSourceLevel of a
// full-resolution pass.
//=========================================================================

in vec2 texCoord;

uniform sampler2DArray deepDistance;
uniform sampler2DArray deepNormal;
uniform sampler2DArray deepRadiance;
uniform sampler2DArray deepAmbient;
uniform sampler2DArray deepAlbedo;
uniform sampler2D deepHistory0;   // (E, distance) of last frame's layer 0
uniform sampler2D deepHistory1;   // (E, distance) of last frame's layer 1
uniform int deepLayers;           // 1 or 2
uniform int deepHasHistory;
uniform mat4 deepToPrevious;
uniform mat4 deepPrevProjection;
uniform vec2 deepHistorySize;     // texels of the history
uniform float deepTolerance;      // world units
uniform float deepDamping;        // delta
uniform int deepBoost;            // eq. 7 on/off
uniform int deepHasLights;        // 0: VTK drew the props unlit, no direct light
uniform int deepSourceLevel;      // MIP level of the output's texels
uniform ivec2 deepBounceSize;     // the output's texels
uniform float deepIrradianceLimit; // the largest half float (RGBA16F output)

//VTK::DeepGBuffer::Common

//VTK::DeepScreenSpace::Common

//VTK::Output::Dec

// B of the layer's surface at `pixel`, at distance d (0: no surface).
vec3 bounceInput(ivec2 pixel, vec2 size, int layer, float d)
{
  if (!(d > 0.0))
  {
    return vec3(0.0);
  }
  // Without a light VTK draws props unlit at their full colour: that is no
  // light arriving from a source, so nothing is bounced.
  vec3 direct = deepHasLights == 0 ? vec3(0.0)
                                   : max(texelFetch(deepRadiance, ivec3(pixel, layer), 0).rgb -
                                         texelFetch(deepAmbient, ivec3(pixel, layer), 0).rgb,
                                       vec3(0.0));
  if (deepHasHistory == 0 || deepDamping <= 0.0)
  {
    return direct;
  }
  vec3 X = deepPositionFromDistance(vec2(pixel) + 0.5, size, d);
  vec3 n = deepGeometricNormal(deepDistance, pixel, layer, size, X, d,
    deepDecodeOct16(texelFetch(deepNormal, ivec3(pixel, layer), 0).rg));
  ivec2 texel;
  float expected;
  if (!deepLastFrameTexel(
        pixel, d, X, n, deepToPrevious, deepPrevProjection, deepHistorySize, texel, expected))
  {
    return direct;
  }
  vec4 h0 = texelFetch(deepHistory0, texel, 0);
  vec4 h1 = texelFetch(deepHistory1, texel, 0);
  float e0 = h0.a > 0.0 ? abs(h0.a - expected) : 1e30;
  float e1 = h1.a > 0.0 ? abs(h1.a - expected) : 1e30;
  float best = min(e0, e1);
  if (!(best <= deepTolerance))
  {
    return direct;
  }
  vec3 previousE = e0 <= e1 ? h0.rgb : h1.rgb;
  vec3 rho = texelFetch(deepAlbedo, ivec3(pixel, layer), 0).rgb;
  return direct + deepDamping * deepReflectance(rho, deepBoost != 0) * previousE / deepPi;
}

void main()
{
  vec2 size = vec2(textureSize(deepDistance, 0).xy);
  ivec2 texel = min(ivec2(texCoord * vec2(deepBounceSize)), deepBounceSize - 1);
  ivec2 pixel = deepRotatedGridSource(texel, deepSourceLevel, ivec2(size));
  // Alpha: whether the layer has a surface there, so that the box-filtered
  // levels of AverageFarTaps hold (mean of B over the block's surfaces) x
  // (their share of the block).
  gl_FragData[1] = vec4(0.0);
  // Layer 1 is the second iteration of a loop that leaves it out where it
  // has no surface: a CPU renderer (Mesa llvmpipe) shades 8 texels in
  // lockstep and runs both sides of a branch, but stops a loop that none
  // of them still runs, and most texels have no layer 1.
  float d1 = deepLayers > 1 ? texelFetch(deepDistance, ivec3(pixel, 1), 0).r : 0.0;
  int layers = d1 > 0.0 ? 2 : 1;
  for (int j = 0; j < layers; ++j)
  {
    float d = j == 0 ? texelFetch(deepDistance, ivec3(pixel, 0), 0).r : d1;
    vec4 result =
      vec4(min(bounceInput(pixel, size, j, d), vec3(deepIrradianceLimit)), d > 0.0 ? 1.0 : 0.0);
    if (j == 0)
    {
      gl_FragData[0] = result;
    }
    else
    {
      gl_FragData[1] = result;
    }
  }
}
