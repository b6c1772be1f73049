//VTK::System::Dec

//=========================================================================
// Deep scalable ambient obscurance (Mara et al. 2016, section 3.1,
// equations 1 and 2) with the spiral taps of section 3.4, or the layers'
// occupied stretches over the sectors of screen-space slices
// (VISIBILITY_BITMASK). Writes the raw ambient visibility AV of layer 0's
// surface (1 where layer 0 is empty).
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
// DEEP_AO_ESTIMATOR: the estimator (DEEP_AO_ESTIMATOR_*), compiled in.
//VTK::DeepAmbientObscurance::Estimator
uniform int deepMaxMip;        // finest..coarsest level index available
uniform float deepMipThreshold; // q, pixels
uniform float deepRotationOffset; // radians added to phi (0 unless temporal)
uniform float deepThickness;   // world units: a surface whose far side no layer holds

// VISIBILITY_BITMASK: sectors per slice, as in Therrien et al. 2023.
const int deepSectors = 32;
const int deepFalloffLevels = 8;

//VTK::DeepGBuffer::Common

//VTK::DeepScreenSpace::Common

//VTK::Output::Dec

// GTAO's slice integral (Jimenez et al. 2016, eq. 10 without its clamp):
// the integral of cos(theta - gamma) |sin theta| from 0 to theta, with theta
// the signed angle from the view vector in the slice and gamma the
// projected normal's. |sin theta| is the sphere's measure around the view
// vector, cos(theta - gamma) the cosine to the normal. The integrand is 2 pi
// periodic and its integral over the circle is 0, so theta beyond +-pi (the
// hemisphere of a normal facing away from the camera) wraps around.
float deepSliceIntegral(float theta, float gamma)
{
  theta += theta > deepPi ? -2.0 * deepPi : (theta < -deepPi ? 2.0 * deepPi : 0.0);
  float s = theta >= 0.0 ? 1.0 : -1.0;
  return s * (0.25 * (cos(gamma) - cos(2.0 * theta - gamma)) + 0.5 * theta * sin(gamma));
}

// acos(x) after Abramowitz and Stegun 4.4.45 (|error| < 7e-5 radians, far
// below a sector's pi / 32): on a CPU renderer the built-in acos costs
// about half of the bitmask estimator's time.
float deepFastAcos(float x)
{
  float a = abs(x);
  float r = sqrt(1.0 - a) * (1.5707288 + a * (-0.2121144 + a * (0.0742610 - 0.0187293 * a)));
  return x >= 0.0 ? r : deepPi - r;
}

// Sector coordinate in [0, 1] of a direction w above X's tangent plane,
// given w.n, w.w and w.across: the slice angle with the same elevation
// (sin e = w.n / |w| = |projected n| cos(theta - gamma)), on the side of the
// projected normal that w lies on (`across`, the slice's direction at
// gamma + pi / 2); 0 and 1 are the tangent plane. A tap off the slice (a MIP
// level's texel centre) keeps its elevation, so that a plane does not
// occlude itself.
float deepSectorCoordinate(float wn, float ww, float wAcross, float inverseProjectedLength)
{
  float e = wn * inversesqrt(max(ww, 1e-30)) * inverseProjectedLength;
  float c = deepFastAcos(clamp(e, -1.0, 1.0)) * (1.0 / deepPi);
  return clamp(wAcross >= 0.0 ? 0.5 + c : 0.5 - c, 0.0, 1.0);
}

// The sectors that the stretch w(s) = a + s D, s in [0, extent] (relative
// to X, D a unit vector), covers within r of X and above X's tangent plane,
// (bits first..last - 1 of `sectors`) and its falloff 1 - t^2 / r^2 at its
// point nearest X; false when no part of it is there. dn = D.n and
// dAcross = D.across (see deepSectorCoordinate).
bool deepStretchSectors(vec3 a, vec3 D, float extent, vec3 n, float dn, vec3 across,
  float dAcross, float inverseProjectedLength, float r2, out uint sectors, out int first,
  out int last, out float falloff)
{
  sectors = 0u;
  first = 0;
  last = 0;
  falloff = 0.0;
  // Within r of X ...
  float along = dot(a, D);
  float aa = dot(a, a);
  float discriminant = along * along - (aa - r2);
  if (!(discriminant > 0.0))
  {
    return false;
  }
  float root = sqrt(discriminant);
  float s0 = max(0.0, -along - root);
  float s1 = min(extent, -along + root);
  // ... and above X's tangent plane.
  float an = dot(a, n);
  if (dn > 0.0)
  {
    s0 = max(s0, -an / dn);
  }
  else if (dn < 0.0)
  {
    s1 = min(s1, -an / dn);
  }
  else if (an < 0.0)
  {
    return false;
  }
  if (!(s1 > s0))
  {
    return false;
  }
  // |w(s)|^2 = aa + 2 s along + s^2, w(s).n = an + s dn.
  float sNearest = clamp(-along, s0, s1);
  falloff = 1.0 - (aa + sNearest * (2.0 * along + sNearest)) / r2;
  float aAcross = dot(a, across);
  float u0 = deepSectorCoordinate(
    an + s0 * dn, aa + s0 * (2.0 * along + s0), aAcross + s0 * dAcross, inverseProjectedLength);
  float u1 = deepSectorCoordinate(
    an + s1 * dn, aa + s1 * (2.0 * along + s1), aAcross + s1 * dAcross, inverseProjectedLength);
  first = int(floor(min(u0, u1) * float(deepSectors) + 0.5));
  last = int(floor(max(u0, u1) * float(deepSectors) + 0.5));
  int count = last - first;
  sectors = count <= 0 ? 0u
    : count >= deepSectors  ? 0xFFFFFFFFu
                            : ((1u << uint(count)) - 1u) << uint(first);
  return true;
}

// A over the sectors of one slice: the falloff levels 0-3 and 4-7 (uvec4
// components) hold the sectors covered with a falloff above
// (l + 1/2) / levels, so a sector's level count / levels is its falloff;
// times the sector's cosine-weighted measure, GTAO's slice integral (sector
// b spans theta = gamma + pi (b / 32 - 1 / 2) .. gamma + pi ((b + 1) / 32 -
// 1 / 2)), times |n projected|. Only sectors first..last - 1 can be
// covered: on a CPU renderer (Mesa llvmpipe) a loop's trip count is the
// only branch that skips work (both sides of an `if` are executed for the
// pixels shaded together), and most pixels have few or no sectors covered.
float deepCoveredObscurance(uvec4 coveredLow, uvec4 coveredHigh, int first, int last, float gamma,
  float projectedLength)
{
  float A = 0.0;
  float previous =
    deepSliceIntegral(gamma + deepPi * (float(first) / float(deepSectors) - 0.5), gamma);
  for (int b = first; b < last; ++b)
  {
    float next =
      deepSliceIntegral(gamma + deepPi * (float(b + 1) / float(deepSectors) - 0.5), gamma);
    uvec4 bits = ((coveredLow >> uint(b)) & 1u) + ((coveredHigh >> uint(b)) & 1u);
    float levels = dot(vec4(bits), vec4(1.0));
    A += levels / float(deepFalloffLevels) * (next - previous);
    previous = next;
  }
  return projectedLength * A;
}

// VISIBILITY_BITMASK over one slice: the slice is the plane through X's view
// ray (V towards the camera) and the screen direction `direction`, where
// `steps` taps per side, at r_p (j + jitter)^2 / steps^2 pixels, find the
// layers' surfaces. Each surface occupies a stretch of its tap's view ray
// (below); the part of it within r of X and above X's tangent plane covers
// an interval of the slice's sectors, and a sector keeps the largest
// falloff 1 - t^2 / r^2 that covers it, its nearest hit's. Returns the
// slice's share of A: the covered sectors' cosine-weighted measure times
// their falloff (1 for a fully covered hemisphere, averaged over slices).
float deepSliceObscurance(vec3 X, vec3 n, vec3 V, vec2 direction, vec2 center, vec2 size,
  float rp, float jitter, int steps)
{
  vec3 screen = vec3(direction, 0.0);
  vec3 ortho = normalize(screen - dot(screen, V) * V);
  vec3 axis = cross(V, ortho);
  vec3 projected = n - axis * dot(n, axis);
  float projectedLength = length(projected);
  float gamma = atan(dot(projected, ortho), dot(projected, V));
  vec3 across = cos(gamma) * ortho - sin(gamma) * V;
  float inverseProjectedLength = 1.0 / max(projectedLength, 1e-6);
  float r2 = deepRadius * deepRadius;
  uvec4 coveredLow = uvec4(0u);  // falloff levels 0-3
  uvec4 coveredHigh = uvec4(0u); // falloff levels 4-7
  int firstCovered = deepSectors;
  int lastCovered = 0;
  for (int j = 0; j < steps; ++j)
  {
    float t = (float(j) + jitter) / float(steps);
    float h = 1.0 + (rp - 1.0) * t * t;
    for (int side = 0; side < 2; ++side)
    {
      ivec2 tap = ivec2(floor(center + (side == 0 ? h : -h) * direction));
      if (any(lessThan(tap, ivec2(0))) || any(greaterThanEqual(tap, ivec2(size))))
      {
        continue;
      }
      // As for the spiral: the texel the MIP level holds, an exact surface
      // point. Its view ray is origin + distance x step, relative to X.
      int m = deepTapMipLevel(h, deepMipThreshold, 0, deepMaxMip);
      ivec2 coarse = deepCoarseTexel(tap, m, ivec2(size));
      vec2 tapCenter = vec2(deepRotatedGridSource(coarse, m, ivec2(size))) + 0.5;
      vec3 origin = deepPositionFromDistance(tapCenter, size, 0.0);
      vec3 step = deepPositionFromDistance(tapCenter, size, 1.0) - origin;
      origin -= X;
      float stepLength = length(step);
      vec3 D = step / stepLength;
      float dn = dot(D, n);
      float dAcross = dot(D, across);
      for (int k = 0; 2 * k < deepLayers; ++k)
      {
        vec4 key = texelFetch(deepKey, ivec3(coarse, k), m);
        // The occupied stretches of the tap's view ray. Layers 2k and
        // 2k + 1 of opposite facings enter and leave one solid, which fills
        // the ray between them. Otherwise the layers do not hold a
        // surface's far side: it is within dz (deepThickness) of a surface
        // with a layer behind it, and the last surface hides everything
        // behind it (a height field, as GTAO assumes everywhere).
        // Stretches are counted, not skipped with a branch: a loop's trip
        // count is what lets a CPU renderer skip work.
        bool hasBack = 2 * k + 1 < deepLayers && key.z > 0.0;
        bool solid = hasBack && (deepKeyBackFace(key.y) != deepKeyBackFace(key.w));
        int stretches = !(key.x > 0.0) ? 0 : (hasBack && !solid ? 2 : 1);
        for (int segment = 0; segment < stretches; ++segment)
        {
          float front = segment == 0 ? key.x : key.z;
          float extent = (segment == 0 && solid) ? (key.z - key.x) * stepLength
            : hasBack                            ? deepThickness
                                                 : 1e30;
          uint sectors;
          int first, last;
          float falloff;
          if (!deepStretchSectors(origin + front * step, D, extent, n, dn, across, dAcross,
                inverseProjectedLength, r2, sectors, first, last, falloff) ||
            sectors == 0u)
          {
            continue;
          }
          firstCovered = min(firstCovered, first);
          lastCovered = max(lastCovered, last);
          float level = falloff * float(deepFalloffLevels);
          coveredLow |= uvec4(greaterThan(vec4(level), vec4(0.5, 1.5, 2.5, 3.5))) * sectors;
          coveredHigh |= uvec4(greaterThan(vec4(level), vec4(4.5, 5.5, 6.5, 7.5))) * sectors;
        }
      }
    }
  }
  return deepCoveredObscurance(
    coveredLow, coveredHigh, firstCovered, lastCovered, gamma, projectedLength);
}

// VISIBILITY_BITMASK: AV = 1 - A over max(1, N / 16) slices at angles
// phi + pi k / slices, N / (2 slices) taps on each side of each; the
// per-pixel rotation phi and the taps' radial jitter differ between
// neighbours, whose values the bilateral filter averages.
float deepBitmaskVisibility(vec3 X, vec3 n, vec3 V, float phi, vec2 center, vec2 size, float rp)
{
  int slices = max(1, deepSamples / 16);
  int steps = max(1, deepSamples / (2 * slices));
  float A = 0.0;
  for (int k = 0; k < slices; ++k)
  {
    float angle = phi + deepPi * float(k) / float(slices);
    A += deepSliceObscurance(
      X, n, V, vec2(cos(angle), sin(angle)), center, size, rp, deepRadialOffset(phi), steps);
  }
  return max(0.0, 1.0 - A / float(slices));
}

// SOLID_ANGLE and EQUATION_1: AV from eq. 2 at N spiral taps.
float deepSpiralVisibility(vec3 X, vec3 n, float footprint, float phi, vec2 center,
  vec2 size, float rp)
{
  float r2 = deepRadius * deepRadius;
  float sum = 0.0;
  float invN = 1.0 / float(deepSamples);
  // Tap i (section 3.4) at h = r_p (i + 1/2) / N pixels from the centre, in
  // the direction theta = 2 pi tau (i + 1/2) / N + phi: the first direction
  // and then steps of 2 pi tau / N (deepRotate).
  float h;
  float theta;
  deepSpiralTapPolar(0, 0.5, deepSamples, deepTurns, rp, phi, h, theta);
  vec2 direction = deepDirection(theta);
  vec2 turn = deepDirection(2.0 * deepPi * deepTurns * invN);
  for (int i = 0; i < deepSamples; ++i)
  {
    deepSpiralTapPolar(i, 0.5, deepSamples, deepTurns, rp, phi, h, theta);
    ivec2 tap = ivec2(floor(center + h * direction));
    direction = deepRotate(direction, turn);
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
      // A layer without a surface has none behind it either. Leaving the
      // loop (not skipping the layer) lets a CPU renderer (Mesa llvmpipe),
      // which runs both sides of a branch for the 8 pixels it shades
      // together, skip layer 1 where none of their taps has one.
      if (!(dy > 0.0))
      {
        break;
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
        if (DEEP_AO_ESTIMATOR == DEEP_AO_ESTIMATOR_SOLID_ANGLE)
        {
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
  // Equation 1 or the linear A = 2 / N sum.
  return DEEP_AO_ESTIMATOR == DEEP_AO_ESTIMATOR_SOLID_ANGLE
    ? max(0.0, 1.0 - 2.0 * invN * sum)
    : max(0.0, 1.0 - sqrt(deepPi * invN * sum));
}

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

  // Screen-space radius r_p: r projected at X's depth (section 3.4).
  float rp = deepScreenRadius(deepRadius, d, size);

  // Per-pixel rotation: interleaved gradient noise of (x, y), plus a
  // frame-dependent offset while accumulating temporally (0 otherwise, so
  // phi is unchanged bit for bit).
  float phi = deepSpiralRotation(pixel) + deepRotationOffset;
  // The view ray through X.
  vec3 ray = normalize(deepPositionFromDistance(center, size, 2.0 * d) - X);

#if DEEP_AO_ESTIMATOR == DEEP_AO_ESTIMATOR_VISIBILITY_BITMASK
  float av = deepBitmaskVisibility(X, n, -ray, phi, center, size, rp);
#else
  float av = deepSpiralVisibility(X, n, deepClipW(d), phi, center, size, rp);
#endif
  // Raised to the Intensity exponent.
  if (deepIntensity != 1.0)
  {
    av = deepIntensity > 0.0 ? (av > 0.0 ? exp2(deepIntensity * log2(av)) : 0.0) : 1.0;
  }
  gl_FragData[0] = vec4(av, 0.0, 0.0, 1.0);
}
