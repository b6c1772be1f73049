//VTK::System::Dec

//=========================================================================
// Deep G-buffer mirror reflections (Mara et al. 2016, section 3.6): for
// each reflective layer-0 pixel, march the mirror ray in camera space and
// test each point against every layer: a hit where the point's distance s
// lies in [d_j, d_j + dz] of layer j and layer j faces the ray. Misses take
// the environment. See vtkDeepReflectionPass.h for the exact definitions.
// Outputs: 0 = (L_r, 1), 1 = (hit layer or -1, hit distance t).
// Untraced pixels are discarded (the targets are cleared to 0 and (-1, 0)).
//=========================================================================

//VTK::DeepReflection::Environment

in vec2 texCoord;

uniform sampler2DArray deepDistance;
uniform sampler2DArray deepNormal;
uniform sampler2DArray deepRadiance;
uniform sampler2DArray deepReflectivity;
uniform int deepLayers;
uniform mat4 deepProjection;   // camera space -> clip space
uniform float deepMaxDistance; // t_max before the frustum cut
uniform float deepThickness;   // dz
uniform int deepMaxSteps;
uniform float deepPixelStride;
uniform int deepRefinements;

// Environment (DEEP_ENVIRONMENT 0: background, 1: equirectangular, 2: cube).
uniform mat3 deepViewToEnvironment; // camera space -> environment frame e
uniform vec3 deepBackground;
uniform vec3 deepBackground2;
uniform int deepGradient;
#if DEEP_ENVIRONMENT == DEEP_ENVIRONMENT_EQUIRECTANGULAR
uniform sampler2D deepEnvironment;
#elif DEEP_ENVIRONMENT == DEEP_ENVIRONMENT_CUBE_MAP
uniform samplerCube deepEnvironment;
#endif

//VTK::DeepGBuffer::Common
//VTK::DeepScreenSpace::Common

//VTK::Output::Dec

vec3 deepEnvironmentRadiance(vec3 r)
{
#if DEEP_ENVIRONMENT == DEEP_ENVIRONMENT_EQUIRECTANGULAR
  vec3 e = normalize(deepViewToEnvironment * r);
  vec2 uv = vec2(atan(e.z, e.x) * (0.5 / 3.14159265358979) + 0.5,
    asin(clamp(e.y, -1.0, 1.0)) * (1.0 / 3.14159265358979) + 0.5);
  return texture(deepEnvironment, uv).rgb;
#elif DEEP_ENVIRONMENT == DEEP_ENVIRONMENT_CUBE_MAP
  return texture(deepEnvironment, normalize(deepViewToEnvironment * r)).rgb;
#else
  return deepGradient != 0 ? mix(deepBackground, deepBackground2, 0.5 + 0.5 * r.y)
                           : deepBackground;
#endif
}

// Projects camera-space q; false when it is behind the camera or outside
// the image. Returns its window coordinate (pixels) in `window`.
bool deepProject(vec3 q, vec2 size, out vec2 window)
{
  vec4 clip = deepProjection * vec4(q, 1.0);
  if (!(clip.w > 0.0))
  {
    window = vec2(1.0e9); // behind the camera: "very far" for the step count
    return false;
  }
  vec2 ndc = clip.xy / clip.w;
  window = (ndc * 0.5 + 0.5) * size;
  return all(greaterThanEqual(ndc, vec2(-1.0))) && all(lessThan(ndc, vec2(1.0)));
}

// The first layer that point q (at window coordinate w) hits, or -1.
int deepHitLayer(vec3 q, vec2 w, vec3 r)
{
  ivec2 texel = ivec2(floor(w));
  float s = -q.z;
  for (int j = 0; j < deepLayers; ++j)
  {
    float d = texelFetch(deepDistance, ivec3(texel, j), 0).r;
    if (d > 0.0 && s >= d && s <= d + deepThickness)
    {
      vec3 n = deepDecodeOct16(texelFetch(deepNormal, ivec3(texel, j), 0).rg);
      if (dot(n, r) < 0.0)
      {
        return j;
      }
    }
  }
  return -1;
}

void main()
{
  vec2 size = vec2(textureSize(deepDistance, 0).xy);
  ivec2 pixel = min(ivec2(texCoord * size), ivec2(size) - 1);
  float d0 = texelFetch(deepDistance, ivec3(pixel, 0), 0).r;
  vec3 reflectivity = texelFetch(deepReflectivity, ivec3(pixel, 0), 0).rgb;
  if (!(d0 > 0.0) || max(reflectivity.r, max(reflectivity.g, reflectivity.b)) <= 0.0)
  {
    discard;
  }
  vec3 x = deepPositionFromDistance(vec2(pixel) + 0.5, size, d0);
  vec3 n = deepDecodeOct16(texelFetch(deepNormal, ivec3(pixel, 0), 0).rg);
  vec3 v = deepProjT.z != 0.0 ? normalize(x) : vec3(0.0, 0.0, -1.0);
  if (dot(n, v) > 0.0)
  {
    n = -n;
  }
  vec3 r = reflect(v, n);

  // The ray's clip coordinates are linear in t: clip(t) = c0 + t c1. Cut
  // t_max where it leaves the view frustum (|x|, |y|, |z| <= w): no step
  // is spent outside the image or beyond the clipping planes.
  vec4 c0 = deepProjection * vec4(x, 1.0);
  vec4 c1 = deepProjection * vec4(r, 0.0);
  float tMax = deepMaxDistance;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side = -1; side <= 1; side += 2)
    {
      float a = c0.w + float(side) * c0[axis];
      float b = c1.w + float(side) * c1[axis];
      if (b < 0.0)
      {
        tMax = min(tMax, max(a, 0.0) / -b);
      }
    }
  }
  tMax = max(tMax, 0.0);

  // Steps: about deepPixelStride pixels each, and at most half the
  // thickness in depth each (so no layer's [d, d + dz] band can be stepped
  // over), at most deepMaxSteps.
  vec2 w0, w1;
  deepProject(x, size, w0);
  deepProject(x + tMax * r, size, w1);
  float lengthPixels = min(length(w1 - w0), 1.0e9);
  float depthSteps = 2.0 * tMax * abs(r.z) / max(deepThickness, 1.0e-30);
  float wanted = max(ceil(lengthPixels / deepPixelStride), ceil(min(depthSteps, 1.0e9)));
  int steps = int(clamp(wanted, 1.0, float(deepMaxSteps)));
  float dt = tMax / float(steps);

  int hit = -1;
  float tHit = 0.0;
  vec2 wHit = vec2(0.0);
  float tPrevious = 0.0;
  for (int i = 1; i <= steps && tMax > 0.0; ++i)
  {
    float t = float(i) * dt;
    vec3 q = x + t * r;
    vec2 w;
    if (!deepProject(q, size, w))
    {
      break; // left the image
    }
    int layer = deepHitLayer(q, w, r);
    if (layer >= 0)
    {
      // Bisection: the entry into [d_j, d_j + dz] lies in (tPrevious, t].
      float lo = tPrevious, hi = t;
      vec2 wHi = w;
      for (int k = 0; k < deepRefinements; ++k)
      {
        float mid = 0.5 * (lo + hi);
        vec3 qm = x + mid * r;
        vec2 wm;
        if (deepProject(qm, size, wm) && deepHitLayer(qm, wm, r) == layer)
        {
          hi = mid;
          wHi = wm;
        }
        else
        {
          lo = mid;
        }
      }
      hit = layer;
      tHit = hi;
      wHit = wHi;
      break;
    }
    tPrevious = t;
  }

  vec3 radiance;
  if (hit >= 0)
  {
    radiance = texelFetch(deepRadiance, ivec3(ivec2(floor(wHit)), hit), 0).rgb;
  }
  else
  {
    radiance = deepEnvironmentRadiance(r);
  }
  gl_FragData[0] = vec4(max(radiance, vec3(0.0)), 1.0);
  gl_FragData[1] = vec4(float(hit), tHit, 0.0, 0.0);
}
