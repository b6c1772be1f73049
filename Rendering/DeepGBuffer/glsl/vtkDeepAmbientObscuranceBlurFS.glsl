//VTK::System::Dec

//=========================================================================
// One direction of the separable bilateral reconstruction of the ambient
// visibility (Mara et al. 2016, section 3.1: normal and plane weights).
// Gaussian spatial weights times a plane weight (distance of the tap's
// surface from the centre's tangent plane, relative to the centre's
// distance) times a normal weight. Taps on other surfaces get weight 0, so
// AV does not bleed across depth or normal discontinuities.
//=========================================================================

in vec2 texCoord;

uniform sampler2D deepInput;       // AV to filter (R32F)
uniform sampler2DArray deepKey; // geometry key (level 0, slice 0: layer 0's .xy)
uniform ivec2 deepAxis;            // (1, 0) horizontal, (0, 1) vertical
uniform int deepBlurRadius;        // taps on each side
uniform float deepPlaneTolerance;  // fraction of the centre's distance

//VTK::DeepGBuffer::Common

//VTK::DeepScreenSpace::Common

// max(0, n.n_Y)^BlurNormalPower, the power compiled in.
//VTK::DeepScreenSpace::NormalWeight

//VTK::Output::Dec

void main()
{
  vec2 size = vec2(textureSize(deepKey, 0).xy);
  ivec2 pixel = min(ivec2(texCoord * size), ivec2(size) - 1);
  float centerValue = texelFetch(deepInput, pixel, 0).r;
  vec2 key = texelFetch(deepKey, ivec3(pixel, 0), 0).xy;
  float d = key.x;
  if (!(d > 0.0))
  {
    gl_FragData[0] = vec4(centerValue, 0.0, 0.0, 1.0);
    return;
  }
  vec3 X = deepPositionFromDistance(vec2(pixel) + 0.5, size, d);
  vec3 n = deepUnpackOct16(key.y);
  float sigma = max(0.5 * float(deepBlurRadius), 0.5);
  float tolerance = deepPlaneTolerance * d;

  float sum = centerValue;
  float weights = 1.0;
  for (int k = -deepBlurRadius; k <= deepBlurRadius; ++k)
  {
    if (k == 0)
    {
      continue;
    }
    ivec2 tap = pixel + k * deepAxis;
    if (!deepShaded(tap))
    {
      continue;
    }
    vec2 tapKey = texelFetch(deepKey, ivec3(tap, 0), 0).xy;
    float dy = tapKey.x;
    if (!(dy > 0.0))
    {
      continue;
    }
    vec3 Y = deepPositionFromDistance(vec2(tap) + 0.5, size, dy);
    vec3 ny = deepUnpackOct16(tapKey.y);
    float w =
      deepBilateralWeight(k, sigma, X, n, Y, deepNormalWeight(max(0.0, dot(n, ny))), tolerance);
    sum += w * texelFetch(deepInput, tap, 0).r;
    weights += w;
  }
  gl_FragData[0] = vec4(sum / weights, 0.0, 0.0, 1.0);
}
