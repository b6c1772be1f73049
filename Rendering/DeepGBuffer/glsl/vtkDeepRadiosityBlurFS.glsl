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
uniform sampler2D deepKey;         // both layers' distance and normal (vtkDeepGeometryKeyFS)
uniform ivec2 deepAxis;            // (1, 0) horizontal, (0, 1) vertical
uniform int deepBlurRadius;        // taps on each side
uniform float deepPlaneTolerance;  // fraction of the centre's distance

//VTK::DeepGBuffer::Common

//VTK::DeepScreenSpace::Common

// max(0, n.n_Y)^BlurNormalPower, the power compiled in.
//VTK::DeepScreenSpace::NormalWeight

//VTK::Output::Dec

// One layer's side of the filter: its centre (position X, normal n, plane
// tolerance) and running sums, in named variables (arrays indexed in a
// loop cost more than the fetch saved on a CPU renderer).
struct Layer
{
  bool Filtered;
  vec3 X;
  vec3 N;
  float Tolerance;
  vec4 Sum;
  float Weights;
};

Layer beginLayer(vec2 geometry, ivec2 pixel, vec2 size, vec4 center)
{
  Layer layer;
  layer.Filtered = geometry.x > 0.0;
  layer.X = deepPositionFromDistance(vec2(pixel) + 0.5, size, geometry.x);
  layer.N = deepUnpackOct16(geometry.y);
  layer.Tolerance = deepPlaneTolerance * geometry.x;
  layer.Sum = center;
  layer.Weights = 1.0;
  return layer;
}

void addTap(inout Layer layer, vec2 geometry, ivec2 tap, vec2 size, int k, float sigma,
  vec4 tapValue)
{
  vec3 Y = deepPositionFromDistance(vec2(tap) + 0.5, size, geometry.x);
  vec3 ny = deepUnpackOct16(geometry.y);
  float normalWeight = deepNormalWeight(max(0.0, dot(layer.N, ny)));
  float w = deepBilateralWeight(k, sigma, layer.X, layer.N, Y, normalWeight, layer.Tolerance);
  layer.Sum += w * tapValue;
  layer.Weights += w;
}

// Both layers in one loop over the taps, so that a tap's geometry is one
// fetch of the key for both.
void main()
{
  ivec2 isize = textureSize(deepKey, 0);
  vec2 size = vec2(isize);
  ivec2 pixel = min(ivec2(texCoord * size), isize - 1);
  vec4 key = texelFetch(deepKey, pixel, 0);
  Layer layer0 = beginLayer(key.xy, pixel, size, texelFetch(deepInput0, pixel, 0));
  Layer layer1 = beginLayer(key.zw, pixel, size, texelFetch(deepInput1, pixel, 0));
  float sigma = max(0.5 * float(deepBlurRadius), 0.5);
  for (int k = -deepBlurRadius; k <= deepBlurRadius && (layer0.Filtered || layer1.Filtered); ++k)
  {
    ivec2 tap = pixel + k * deepAxis;
    if (k == 0 || !deepShaded(tap))
    {
      continue;
    }
    vec4 tapKey = texelFetch(deepKey, tap, 0);
    if (layer0.Filtered && tapKey.x > 0.0)
    {
      addTap(layer0, tapKey.xy, tap, size, k, sigma, texelFetch(deepInput0, tap, 0));
    }
    if (layer1.Filtered && tapKey.z > 0.0)
    {
      addTap(layer1, tapKey.zw, tap, size, k, sigma, texelFetch(deepInput1, tap, 0));
    }
  }
  gl_FragData[0] = layer0.Sum / layer0.Weights;
  gl_FragData[1] = layer1.Sum / layer1.Weights;
}
