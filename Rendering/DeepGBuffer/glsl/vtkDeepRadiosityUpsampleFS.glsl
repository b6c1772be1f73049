//VTK::System::Dec

//=========================================================================
// Joint bilateral upsampling of deep screen-space radiosity gathered at a
// reduced resolution (vtkDeepRadiosityPass::SetResolutionDivisor D > 1),
// for layers 0 and 1 at once. Reduced texel q stands for layer texel D q
// (the gather's receivers). A layer texel P takes the irradiance E_t and
// confidence c of the 3 x 3 reduced texels around P / D, each weighted by
// a tent of radius 1.5 texels per axis times a plane weight
// max(0, 1 - |(Y_q - X).n| / (t d)) (Y_q's distance from P's tangent plane,
// t = BlurPlaneTolerance relative to P's distance d, so that light does not
// leak across silhouettes) times a normal weight max(0, n.n_q)^8 (nor
// across creases); when no texel passes, the one nearest to the plane.
// The outgoing radiance is then eq. 6 with P's own albedo
// (deepOutgoingIndirect), so that albedo edges stay sharp; only the
// irradiance is interpolated. Outputs (L, c) of
// layers 0 and 1; 0 where the layer is empty or no reduced texel has a
// surface.
//=========================================================================

in vec2 texCoord;

uniform sampler2DArray deepDistance;    // the layers
uniform sampler2DArray deepNormal;
uniform sampler2DArray deepAlbedo;
uniform sampler2DArray deepReducedNormal;
uniform sampler2D deepHistory0;         // reduced (E_t, distance) of layer 0
uniform sampler2D deepHistory1;
uniform sampler2D deepReducedIndirect0; // reduced (L, c) of layer 0
uniform sampler2D deepReducedIndirect1;
uniform int deepDivisor;                // D
uniform float deepPlaneTolerance;       // of the plane weight, relative to the distance
uniform ivec2 deepReducedMin;           // the reduced texels with results
uniform ivec2 deepReducedMax;           // (exclusive)
uniform int deepLayers;
uniform int deepBoost;
uniform int deepFallback;
uniform vec3 deepEnvironment;

//VTK::DeepGBuffer::Common

//VTK::DeepScreenSpace::Common

//VTK::Output::Dec

vec4 upsampleLayer(ivec2 pixel, vec2 size, int layer)
{
  float d = texelFetch(deepDistance, ivec3(pixel, layer), 0).r;
  if (layer >= deepLayers || !(d > 0.0))
  {
    return vec4(0.0);
  }
  vec3 n = deepDecodeOct16(texelFetch(deepNormal, ivec3(pixel, layer), 0).rg);
  vec3 X = deepPositionFromDistance(vec2(pixel) + 0.5, size, d);
  ivec2 last = ivec2(size) - 1;
  vec2 u = vec2(pixel) / float(deepDivisor);
  ivec2 qc = ivec2(floor(u + 0.5));
  vec4 sum = vec4(0.0);
  float weightSum = 0.0;
  vec4 nearest = vec4(0.0);
  float nearestError = 1e30;
  for (int k = 0; k < 9; ++k)
  {
    ivec2 q = qc + ivec2(k % 3 - 1, k / 3 - 1);
    if (any(lessThan(q, deepReducedMin)) || any(greaterThanEqual(q, deepReducedMax)))
    {
      continue;
    }
    vec4 h = layer == 0 ? texelFetch(deepHistory0, q, 0) : texelFetch(deepHistory1, q, 0);
    if (!(h.a > 0.0))
    {
      continue;
    }
    float c = layer == 0 ? texelFetch(deepReducedIndirect0, q, 0).a
                         : texelFetch(deepReducedIndirect1, q, 0).a;
    vec4 value = vec4(h.rgb, c);
    // The receiver's point: layer texel D q (clamped), at its distance.
    vec3 Y = deepPositionFromDistance(vec2(min(q * deepDivisor, last)) + 0.5, size, h.a);
    float error = abs(dot(Y - X, n));
    if (error < nearestError)
    {
      nearestError = error;
      nearest = value;
    }
    vec3 nq = deepDecodeOct16(texelFetch(deepReducedNormal, ivec3(q, layer), 0).rg);
    vec2 tent = max(vec2(0.0), 1.0 - abs(vec2(q) - u) / 1.5);
    float w = tent.x * tent.y * max(0.0, 1.0 - error / (deepPlaneTolerance * d)) *
      pow(max(0.0, dot(n, nq)), 8.0);
    sum += w * value;
    weightSum += w;
  }
  if (nearestError == 1e30)
  {
    return vec4(0.0);
  }
  vec4 Ec = weightSum > 1e-4 ? sum / weightSum : nearest;
  vec3 rho = texelFetch(deepAlbedo, ivec3(pixel, layer), 0).rgb;
  return deepOutgoingIndirect(rho, Ec.rgb, Ec.a, deepBoost != 0, deepFallback != 0, deepEnvironment);
}

void main()
{
  vec2 size = vec2(textureSize(deepDistance, 0).xy);
  ivec2 pixel = min(ivec2(texCoord * size), ivec2(size) - 1);
  gl_FragData[0] = upsampleLayer(pixel, size, 0);
  gl_FragData[1] = upsampleLayer(pixel, size, 1);
}
