//VTK::System::Dec

//=========================================================================
// One direction of the separable bilateral reconstruction of the radiosity
// (Mara et al. 2016, sections 3.1-3.2: normal and plane weights), for
// layers 0 and 1 at once; each layer is filtered with its own distances
// and normals, RGB irradiance and confidence alike (RGBA). Empty texels and
// texels on other surfaces get weight 0.
//=========================================================================

in vec2 texCoord;

uniform sampler2D deepInput0;      // (E, confidence) of layer 0
uniform sampler2D deepInput1;      // (E, confidence) of layer 1
uniform sampler2DArray deepDistance;
uniform sampler2DArray deepNormal;
uniform int deepLayers;
uniform ivec2 deepAxis;            // (1, 0) horizontal, (0, 1) vertical
uniform int deepBlurRadius;        // taps on each side
uniform float deepPlaneTolerance;  // fraction of the centre's distance
uniform float deepNormalPower;

//VTK::DeepGBuffer::Common

//VTK::DeepScreenSpace::Common

//VTK::Output::Dec

vec4 value(int layer, ivec2 p)
{
  return layer == 0 ? texelFetch(deepInput0, p, 0) : texelFetch(deepInput1, p, 0);
}

vec4 filterLayer(ivec2 pixel, vec2 size, int layer)
{
  vec4 center = value(layer, pixel);
  float d = texelFetch(deepDistance, ivec3(pixel, layer), 0).r;
  if (layer >= deepLayers || !(d > 0.0))
  {
    return center;
  }
  vec3 X = deepPositionFromDistance(vec2(pixel) + 0.5, size, d);
  vec3 n = deepDecodeOct16(texelFetch(deepNormal, ivec3(pixel, layer), 0).rg);
  float sigma = max(0.5 * float(deepBlurRadius), 0.5);
  float tolerance = deepPlaneTolerance * d;
  vec4 sum = center;
  float weights = 1.0;
  for (int k = -deepBlurRadius; k <= deepBlurRadius; ++k)
  {
    ivec2 tap = pixel + k * deepAxis;
    if (k == 0 || !deepShaded(tap))
    {
      continue;
    }
    float dy = texelFetch(deepDistance, ivec3(tap, layer), 0).r;
    if (!(dy > 0.0))
    {
      continue;
    }
    vec3 Y = deepPositionFromDistance(vec2(tap) + 0.5, size, dy);
    vec3 ny = deepDecodeOct16(texelFetch(deepNormal, ivec3(tap, layer), 0).rg);
    float w = deepBilateralWeight(k, sigma, X, n, Y, ny, tolerance, deepNormalPower);
    sum += w * value(layer, tap);
    weights += w;
  }
  return sum / weights;
}

void main()
{
  vec2 size = vec2(textureSize(deepDistance, 0).xy);
  ivec2 pixel = min(ivec2(texCoord * size), ivec2(size) - 1);
  gl_FragData[0] = filterLayer(pixel, size, 0);
  gl_FragData[1] = filterLayer(pixel, size, 1);
}
