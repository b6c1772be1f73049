//VTK::System::Dec

//=========================================================================
// Deep scalable ambient obscurance (Mara et al. 2016, section 3.1,
// equations 1 and 2) with the spiral taps of section 3.4. Writes the raw
// ambient visibility AV of layer 0's surface (1 where layer 0 is empty).
//=========================================================================

in vec2 texCoord;

uniform sampler2DArray deepKey; // geometry key pyramid, two layers per slice
uniform int deepLayers;        // layers searched for occluders (1 = layer 0 only)
uniform int deepSamples;       // N
uniform float deepTurns;       // tau(N), Listing 3
uniform float deepRadius;      // r, world units
uniform float deepBias;        // beta, world units
uniform float deepEpsilon;     // epsilon, world units squared
uniform float deepIntensity;   // exponent applied to AV
uniform int deepEstimator;     // DEEP_AO_ESTIMATOR_*
uniform int deepMaxMip;        // finest..coarsest level index available
uniform float deepMipThreshold; // q, pixels
uniform float deepRotationOffset; // radians added to phi (0 unless temporal)

//VTK::DeepGBuffer::Common

//VTK::DeepScreenSpace::Common

//VTK::Output::Dec

void main()
{
  vec2 size = vec2(textureSize(deepKey, 0).xy);
  ivec2 pixel = min(ivec2(texCoord * size), ivec2(size) - 1);
  vec4 key = texelFetch(deepKey, ivec3(pixel, 0), 0);
  float d = key.x;
  if (!(d > 0.0))
  {
    gl_FragData[0] = vec4(1.0);
    return;
  }
  vec2 center = vec2(pixel) + 0.5;
  vec3 X = deepPositionFromDistance(center, size, d);
  vec3 n = deepUnpackOct16(key.y);
  float r2 = deepRadius * deepRadius;

  // Screen-space radius r_p: r projected at X's depth (section 3.4).
  float rp = deepScreenRadius(deepRadius, d, size);

  // Per-pixel rotation: interleaved gradient noise of (x, y), plus a
  // frame-dependent offset while accumulating temporally (0 otherwise, so
  // phi is unchanged bit for bit).
  float phi = deepSpiralRotation(pixel) + deepRotationOffset;
  // The view ray through X and X's pixel footprint (SOLID_ANGLE weights).
  vec3 ray = normalize(deepPositionFromDistance(center, size, 2.0 * d) - X);
  float footprint = deepClipW(d);

  float sum = 0.0;
  float invN = 1.0 / float(deepSamples);
  for (int i = 0; i < deepSamples; ++i)
  {
    float h;
    ivec2 tap = ivec2(floor(deepSpiralTap(i, 0.5, deepSamples, deepTurns, rp, phi, center, h)));
    if (any(lessThan(tap, ivec2(0))) || any(greaterThanEqual(tap, ivec2(size))))
    {
      continue;
    }
    // MIP level m_i (section 3.4). The coarse texel holds the geometry of
    // one level-0 texel (the rotated grid's choice); the tap's point is
    // reconstructed at THAT texel's centre, so it is an exact surface point
    // (SAO reconstructs at the tap's own centre with the coarse distance
    // instead). One fetch gives two layers' distances and normals.
    int m = deepTapMipLevel(h, deepMipThreshold, 0, deepMaxMip);
    ivec2 coarse = deepCoarseTexel(tap, m, ivec2(size));
    vec2 tapCenter = vec2(deepRotatedGridSource(coarse, m, ivec2(size))) + 0.5;
    float best = 0.0; // max(0, A_i^0, A_i^1, ...)
    vec4 tapKey = vec4(0.0);
    for (int j = 0; j < deepLayers; ++j)
    {
      if ((j & 1) == 0)
      {
        tapKey = texelFetch(deepKey, ivec3(coarse, j >> 1), m);
      }
      vec2 geometry = (j & 1) == 0 ? tapKey.xy : tapKey.zw;
      float dy = geometry.x;
      if (!(dy > 0.0))
      {
        continue;
      }
      vec3 v = deepPositionFromDistance(tapCenter, size, dy) - X;
      float vv = dot(v, v);
      if (vv < r2)
      {
        // Equation 2, or its solid-angle form: a tap at screen distance h
        // stands for a patch whose solid angle seen from X is about
        // (its share of the disc) x r / |v|, so O r / |v| averages to A / 2
        // (see the class description).
        float falloff = 1.0 - vv / r2;
        float o;
        if (deepEstimator == DEEP_AO_ESTIMATOR_SOLID_ANGLE)
        {
          float along = dot(v, ray);
          float across = sqrt(max(vv - along * along, 0.0));
          float t2 = vv + deepEpsilon;
          vec3 ny = deepUnpackOct16(geometry.y);
          vec3 rayY = normalize(deepPositionFromDistance(tapCenter, size, 2.0 * dy) - (v + X));
          float cosCamera = max(abs(dot(ny, rayY)), 0.1);
          float cosX = abs(dot(ny, v)) * inversesqrt(max(vv, 1e-30));
          o = falloff * max(dot(v, n) - deepBias, 0.0) * deepRadius * (deepClipW(dy) / footprint) *
            vv / (t2 * t2) * cosX / cosCamera;
        }
        else
        {
          o = falloff * max((dot(v, n) - deepBias) / sqrt(vv + deepEpsilon), 0.0);
        }
        best = max(best, o);
      }
    }
    sum += best;
  }
  // Equation 1 or the linear A = 2 / N sum, raised to the Intensity exponent.
  float av = deepEstimator == DEEP_AO_ESTIMATOR_SOLID_ANGLE ? max(0.0, 1.0 - 2.0 * invN * sum)
                                                            : max(0.0, 1.0 - sqrt(deepPi * invN * sum));
  if (deepIntensity != 1.0)
  {
    av = deepIntensity > 0.0 ? (av > 0.0 ? exp2(deepIntensity * log2(av)) : 0.0) : 1.0;
  }
  gl_FragData[0] = vec4(av, 0.0, 0.0, 1.0);
}
