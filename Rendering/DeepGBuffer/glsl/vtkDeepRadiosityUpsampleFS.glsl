//VTK::System::Dec

//=========================================================================
// Joint bilateral upsampling of deep screen-space radiosity gathered at a
// reduced resolution (vtkDeepRadiosityPass::SetResolutionDivisor D > 1),
// for layer 0 (the one composited; layer 1's outgoing radiance stays on the
// grid, where the next frame's bounce input reads its irradiance). Reduced
// texel q stands for layer texel D q
// (the gather's receivers). A layer texel P takes the irradiance E_t and
// confidence c of the 2 x 2 reduced texels around P / D, each weighted by
// its bilinear weight times a plane weight
// max(0, 1 - |(Y_q - X).n| / (t d)) (Y_q's distance from P's tangent plane,
// t = BlurPlaneTolerance relative to P's distance d, so that light does not
// leak across silhouettes) times a normal weight max(0, n.n_q)^8 (nor
// across creases); when no texel passes, the one nearest to the plane.
// The outgoing radiance is then eq. 6 with P's own albedo
// (deepOutgoingIndirect), so that albedo edges stay sharp; only the
// irradiance is interpolated, after the still image's bounce extrapolation
// (deepExtrapolation, from the last frame's history). Output: (L, c) of
// layer 0; 0 where the layer is empty or no reduced texel has a surface.
//=========================================================================

in vec2 texCoord;

uniform sampler2DArray deepDistance;    // the layers
uniform sampler2DArray deepNormal;
uniform sampler2DArray deepAlbedo;
uniform sampler2DArray deepReducedNormal;
uniform sampler2D deepHistory0;         // reduced (E_t, distance) of layer 0
uniform sampler2D deepPreviousHistory0; // the same of the last frame
uniform float deepExtrapolation;        // rho / (1 - rho), 0: none
uniform float deepIrradianceLimit;
uniform sampler2D deepReducedIndirect0; // reduced (L, c) of layer 0
uniform int deepDivisor;                // D
uniform float deepPlaneTolerance;       // of the plane weight, relative to the distance
uniform ivec2 deepReducedMin;           // the reduced texels with results
uniform ivec2 deepReducedMax;           // (exclusive)
uniform int deepBoost;
uniform int deepFallback;
uniform vec3 deepEnvironment;

//VTK::DeepGBuffer::Common

//VTK::DeepScreenSpace::Common

//VTK::Output::Dec

vec4 upsampleLayer0(ivec2 pixel, vec2 size)
{
  const int layer = 0;
  float d = texelFetch(deepDistance, ivec3(pixel, layer), 0).r;
  if (!(d > 0.0))
  {
    return vec4(0.0);
  }
  vec3 n = deepDecodeOct16(texelFetch(deepNormal, ivec3(pixel, layer), 0).rg);
  vec3 X = deepPositionFromDistance(vec2(pixel) + 0.5, size, d);
  ivec2 last = ivec2(size) - 1;
  vec2 u = vec2(pixel) / float(deepDivisor);
  ivec2 q0 = ivec2(floor(u));
  vec2 f = u - vec2(q0);
  vec4 sum = vec4(0.0);
  float weightSum = 0.0;
  vec4 nearest = vec4(0.0);
  float nearestError = 1e30;
  // Every reduced texel's terms are computed and its tests folded into
  // conditions, without a `continue`: a CPU renderer (Mesa llvmpipe) runs
  // a loop's `continue` at a high cost (see vtkDeepRadiosityFS).
  ivec2 lastReduced = textureSize(deepHistory0, 0) - 1;
  for (int k = 0; k < 4; ++k)
  {
    ivec2 offset = ivec2(k & 1, k >> 1);
    ivec2 q = q0 + offset;
    ivec2 fetched = clamp(q, ivec2(0), lastReduced);
    vec4 h = texelFetch(deepHistory0, fetched, 0);
    bool usable = all(greaterThanEqual(q, deepReducedMin)) && all(lessThan(q, deepReducedMax)) &&
      h.a > 0.0;
    vec4 previous =
      deepExtrapolation > 0.0 ? texelFetch(deepPreviousHistory0, fetched, 0) : vec4(0.0);
    vec3 E = deepExtrapolateBounces(h.rgb, previous, h.a, deepExtrapolation, deepIrradianceLimit);
    vec4 value = vec4(E, texelFetch(deepReducedIndirect0, fetched, 0).a);
    // The receiver's point: layer texel D q (clamped), at its distance.
    vec3 Y = deepPositionFromDistance(vec2(min(q * deepDivisor, last)) + 0.5, size, h.a);
    float error = abs(dot(Y - X, n));
    if (usable && error < nearestError)
    {
      nearestError = error;
      nearest = value;
    }
    vec3 nq = deepDecodeOct16(texelFetch(deepReducedNormal, ivec3(fetched, layer), 0).rg);
    vec2 b = mix(vec2(1.0) - f, f, vec2(offset));
    float facing = max(0.0, dot(n, nq));
    facing *= facing;
    facing *= facing;
    float w = b.x * b.y * max(0.0, 1.0 - error / (deepPlaneTolerance * d)) * facing * facing;
    if (usable)
    {
      sum += w * value;
      weightSum += w;
    }
  }
  if (nearestError == 1e30)
  {
    return vec4(0.0);
  }
  vec4 Ec = weightSum > 1e-4 ? sum / weightSum : nearest;
  vec3 rho = texelFetch(deepAlbedo, ivec3(pixel, layer), 0).rgb;
  return deepOutgoingIndirect(
    rho, Ec.rgb, Ec.a, deepBoost != 0, deepFallback != 0, deepEnvironment, deepIrradianceLimit);
}

void main()
{
  vec2 size = vec2(textureSize(deepDistance, 0).xy);
  ivec2 pixel = min(ivec2(texCoord * size), ivec2(size) - 1);
  gl_FragData[0] = upsampleLayer0(pixel, size);
}
