//=========================================================================
// Shared GLSL for the screen-space passes over the deep G-buffer (ambient
// obscurance, radiosity): camera-space position reconstruction, the
// section 3.4 spiral taps with their rotation and MIP level, the
// rotated-grid texel a MIP level stands for, and reverse reprojection into
// the previous frame.
//=========================================================================

// The texels a pass shades (vtkDeepScreenSpace::ShadedRegion): the frame and
// the shaded fraction of the guard band, [deepShadedMin, deepShadedMax).
// Gathers read the whole layers (the guard band's input); filters and
// temporal history read only shaded texels, the only ones with results.
uniform ivec2 deepShadedMin;
uniform ivec2 deepShadedMax;

bool deepShaded(ivec2 texel)
{
  return all(greaterThanEqual(texel, deepShadedMin)) && all(lessThan(texel, deepShadedMax));
}

// Camera-space position of the surface at distance d (along -z, z = -d)
// seen through window pixel coordinate p (pixel centres at +0.5) of an
// image of size `size`. deepProjXY = (P00, P11, P02, P12),
// deepProjT = (P03, P13, P32, P33) of the projection the layers were
// rasterised with (perspective: P32 = -1, P33 = 0; parallel: P32 = 0,
// P33 = 1): clip.x = P00 x + P02 z + P03, clip.w = P32 z + P33.
uniform vec4 deepProjXY;
uniform vec4 deepProjT;

const float deepPi = 3.14159265358979;

float deepClipW(float d)
{
  return -deepProjT.z * d + deepProjT.w;
}

vec3 deepPositionFromDistance(vec2 p, vec2 size, float d)
{
  vec2 ndc = p / size * 2.0 - 1.0;
  float z = -d;
  float w = deepClipW(d);
  return vec3((ndc.x * w - deepProjXY.z * z - deepProjT.x) / deepProjXY.x,
    (ndc.y * w - deepProjXY.w * z - deepProjT.y) / deepProjXY.y, z);
}

// Screen-space radius r_p in pixels of the world radius r at distance d
// (section 3.4): r projected at the point's depth.
float deepScreenRadius(float r, float d, vec2 size)
{
  return r * deepProjXY.y * 0.5 * size.y / deepClipW(d);
}

// Per-pixel rotation phi of the spiral: 2 pi times Jimenez's interleaved
// gradient noise of the integer pixel coordinates.
float deepSpiralRotation(ivec2 pixel)
{
  return 2.0 * deepPi *
    fract(52.9829189 * fract(dot(vec2(pixel), vec2(0.06711056, 0.00583715))));
}

// Tap i of N (section 3.4) at `offset` in [0, 1) across its ring:
// kappa = (i + offset) / N, h = r_p kappa (pixels from the centre) and
// theta = 2 pi kappa tau + phi (radians); the paper's taps have offset 0.5.
void deepSpiralTapPolar(int i, float offset, int n, float turns, float rp, float phi, out float h,
  out float theta)
{
  float kappa = (float(i) + offset) / float(n);
  h = rp * kappa;
  theta = 2.0 * deepPi * kappa * turns + phi;
}

// The unit vector at angle theta.
vec2 deepDirection(float theta)
{
  return vec2(cos(theta), sin(theta));
}

// `direction` turned by the angle whose cosine and sine are `turn`. The
// obscurance's spiral taps lie at equal steps of angle, so one cosine and
// sine for the first tap and a rotation for each next one give their
// directions: a CPU renderer (Mesa llvmpipe) computes a cosine and a sine as
// polynomials, 4 % of the obscurance's gather when taken at every tap.
// After N steps the directions differ from the exact ones by about N float
// roundings, far below a texel at the gather's radius.
vec2 deepRotate(vec2 direction, vec2 turn)
{
  return vec2(direction.x * turn.x - direction.y * turn.y,
    direction.x * turn.y + direction.y * turn.x);
}

// A per-pixel offset of the taps across their rings, from the spiral's
// rotation phi: fract(4 phi / (2 pi)). The pairs (phi, offset) lie on a
// rank-1 lattice, so neighbouring pixels, whose rotations the interleaved
// gradient noise spreads over the circle, also spread their offsets over
// the ring's width.
float deepRadialOffset(float phi)
{
  return fract(phi * (2.0 / deepPi));
}

// MIP level of a tap at h pixels: clamp(floor(log2(h / q)), minLevel,
// maxLevel) (section 3.4; minLevel is Table 2's minimum MIP level).
int deepTapMipLevel(float h, float q, int minLevel, int maxLevel)
{
  int m = minLevel;
  if (maxLevel > 0 && h >= 2.0 * q)
  {
    m = max(m, int(floor(log2(h / q))));
  }
  return min(m, maxLevel);
}

// The level-`to` texel that the rotated-grid pyramid (SAO's minification:
// level m + 1 texel (x, y) is level m texel (2x + (y & 1), 2y + (x & 1)),
// clamped) stores at texel `coarse` of level `from` >= `to`, for layers of
// `size` texels. The k = from - to steps in closed form: the parity bits
// they append alternate between y & 1 and x & 1, so
//   x_k = 2^k x + A_k (y & 1) + A_{k-1} (x & 1),
//   y_k = 2^k y + A_k (x & 1) + A_{k-1} (y & 1),
// with A_k = binary 1010... (k digits), 0x2AAAAAAA >> (30 - k). A texel of a
// level (levels have floor(size / 2^m) texels) has all its descendants
// inside the levels below, where the minification's clamp changes nothing;
// only a level wider than the image in one direction (max(size >> m, 1)
// texels) needs the final clamp. A loop over the levels, whose trip count
// differs between the taps a CPU renderer (Mesa llvmpipe) shades together,
// took about a tenth of the radiosity's gather.
ivec2 deepRotatedGridDescend(ivec2 coarse, int from, int to, ivec2 size)
{
  int k = from - to;
  int a = int(0x2AAAAAAAu >> uint(30 - k));
  int b = int(0x2AAAAAAAu >> uint(31 - k));
  ivec2 parity = coarse & 1;
  return min((coarse << k) + a * parity.yx + b * parity, max(size >> to, ivec2(1)) - 1);
}

// The level-0 texel that the rotated-grid pyramid stores at texel `coarse`
// of level m. Reading level-0 data there is exactly reading level m of a
// pyramid built that way.
ivec2 deepRotatedGridSource(ivec2 coarse, int m, ivec2 size)
{
  return deepRotatedGridDescend(coarse, m, 0, size);
}

// The level-m texel containing window point `tap` (clamped to level m).
ivec2 deepCoarseTexel(ivec2 tap, int m, ivec2 size)
{
  return min(tap >> m, max(size >> m, ivec2(1)) - 1);
}

// Reverse reprojection of the current camera-space point X into the
// previous frame: toPrevious = V_prev * inverse(V_now), prevProjection the
// previous projection. Returns false when the point is behind the previous
// camera or outside the texels the previous frame shaded; else the previous
// texel and the point's distance (along -z) in the previous camera.
bool deepReproject(vec3 X, mat4 toPrevious, mat4 prevProjection, vec2 size, out ivec2 texel,
  out float distance)
{
  vec4 P = toPrevious * vec4(X, 1.0);
  distance = -P.z;
  vec4 clip = prevProjection * P;
  texel = ivec2(0);
  if (!(distance > 0.0) || !(clip.w > 0.0))
  {
    return false;
  }
  vec2 prev = (clip.xy / clip.w * 0.5 + 0.5) * size;
  if (!(all(greaterThanEqual(prev, vec2(0.0))) && all(lessThan(prev, size))))
  {
    return false;
  }
  texel = min(ivec2(floor(prev)), ivec2(size) - 1);
  return deepShaded(texel);
}

// Weight of a bilateral reconstruction tap k pixels from the centre
// (section 3.1: normal and plane weights, after [SGNS07]): a Gaussian of
// k (sigma pixels) times a plane weight
// max(0, 1 - |(Y - X).n| / tolerance) (Y's distance from the centre's
// tangent plane) times a normal weight max(0, n.n_Y)^p, so that values do
// not blur across depth or normal discontinuities. The filter computes the
// normal weight (deepNormalWeight, compiled with its power p).
float deepBilateralWeight(
  int k, float sigma, vec3 X, vec3 n, vec3 Y, float normalWeight, float tolerance)
{
  float plane = max(0.0, 1.0 - abs(dot(Y - X, n)) / tolerance);
  return exp(-float(k * k) / (2.0 * sigma * sigma)) * plane * normalWeight;
}

// rho * boost(rho) of the paper's eq. 6: with useBoost, eq. 7's
// boost(rho) = (max rho - min rho) / max rho (0 for grey and black);
// otherwise boost = 1, which conserves energy.
vec3 deepReflectance(vec3 rho, bool useBoost)
{
  if (!useBoost)
  {
    return rho;
  }
  float hi = max(rho.r, max(rho.g, rho.b));
  float lo = min(rho.r, min(rho.g, rho.b));
  return hi > 0.0 ? rho * ((hi - lo) / hi) : vec3(0.0);
}

// Bounce extrapolation of still images (vtkDeepRadiosityPass::
// ExtrapolateBounces): E plus the bounces still to come, `factor` times the
// last increment, where the last frame's (E, distance) `previous` is of the
// same surface (the camera is still: the same texel, the same distance).
vec3 deepExtrapolateBounces(vec3 E, vec4 previous, float distance, float factor, float limit)
{
  if (factor > 0.0 && previous.a > 0.0 && previous.a == distance)
  {
    return clamp(E + factor * (E - previous.rgb), vec3(0.0), vec3(limit));
  }
  return E;
}

// (L, c): the outgoing indirect radiance L = rho boost(rho) E / pi (eq. 6)
// of a surface of albedo rho receiving E with confidence c, blended with the
// environment fallback c L + (1 - c) rho E_env / pi when `fallback` is on
// (section 3.2, Figure 9); L at most `limit`.
vec4 deepOutgoingIndirect(vec3 rho, vec3 E, float c, bool boost, bool fallback, vec3 environment,
  float limit)
{
  c = clamp(c, 0.0, 1.0);
  vec3 L = deepReflectance(rho, boost) * E / deepPi;
  if (fallback)
  {
    L = c * L + (1.0 - c) * rho * environment / deepPi;
  }
  return vec4(min(L, vec3(limit)), c);
}

// Camera-space point at distance d on the ray through `ndc` of a camera
// with projection m (GLSL column-major: m[c][r] = P_rc).
vec3 deepRayPoint(vec2 ndc, float d, mat4 m)
{
  float z = -d;
  float w = m[2][3] * z + m[3][3];
  return vec3((ndc.x * w - m[2][0] * z - m[3][0]) / m[0][0],
    (ndc.y * w - m[2][1] * z - m[3][1]) / m[1][1], z);
}

// The step from X (the surface at `pixel`, distance d, of `layer`) to its
// neighbour one texel along `axis`, taken on the side whose distance is
// closer to d, so that a silhouette on one side does not bend the plane;
// 0 when neither side has a surface.
vec3 deepNeighbourStep(sampler2DArray distances, ivec2 pixel, int layer, vec2 size, vec3 X,
  float d, ivec2 axis)
{
  ivec2 last = ivec2(size) - 1;
  ivec2 a = pixel + axis;
  ivec2 b = pixel - axis;
  float da = all(lessThanEqual(a, last)) ? texelFetch(distances, ivec3(a, layer), 0).r : 0.0;
  float db =
    all(greaterThanEqual(b, ivec2(0))) ? texelFetch(distances, ivec3(b, layer), 0).r : 0.0;
  if (da > 0.0 && (!(db > 0.0) || abs(da - d) <= abs(db - d)))
  {
    return deepPositionFromDistance(vec2(a) + 0.5, size, da) - X;
  }
  if (db > 0.0)
  {
    return X - deepPositionFromDistance(vec2(b) + 0.5, size, db);
  }
  return vec3(0.0);
}

// The normal of the plane the layer's distances describe at `pixel` (the
// rasterised triangle's, where both neighbours lie on it), on the side of
// the shading normal n; n itself where the neighbours give no plane. The
// shading normal is interpolated from the vertices and can differ from the
// triangle's plane by tens of degrees on a coarse mesh (an iso-surface), too
// much to extrapolate a distance with over a texel or two.
vec3 deepGeometricNormal(sampler2DArray distances, ivec2 pixel, int layer, vec2 size, vec3 X,
  float d, vec3 n)
{
  vec3 g = cross(deepNeighbourStep(distances, pixel, layer, size, X, d, ivec2(1, 0)),
    deepNeighbourStep(distances, pixel, layer, size, X, d, ivec2(0, 1)));
  float gg = dot(g, g);
  if (!(gg > 0.0))
  {
    return n;
  }
  g *= inversesqrt(gg);
  return dot(g, n) < 0.0 ? -g : g;
}

// The distance that a reprojected surface should have at the centre of
// the previous texel it fell into: the plane through the current point X
// with normal n, both moved into the previous camera, met by the ray
// through that texel's centre. A reprojected point is generally not at the
// texel centre (under camera motion, or when the history is on a reduced
// grid), and on a slanted surface the stored distance there differs from
// the point's own by up to a texel's footprint times the slope; comparing
// with this extrapolation instead keeps the history of planar surfaces. At
// grazing angles (|n.ray| < 0.05) the point's own distance is used.
float deepExpectedPreviousDistance(vec3 X, vec3 n, mat4 toPrevious, mat4 prevProjection,
  ivec2 texel, vec2 size)
{
  vec3 P = (toPrevious * vec4(X, 1.0)).xyz;
  vec3 np = mat3(toPrevious) * n;
  vec2 ndc = (vec2(texel) + 0.5) / size * 2.0 - 1.0;
  vec3 A = deepRayPoint(ndc, 0.0, prevProjection);
  vec3 B = deepRayPoint(ndc, 1.0, prevProjection) - A;
  float nb = dot(np, B);
  if (!(abs(nb) >= 0.05 * length(B)))
  {
    return -P.z;
  }
  return dot(np, P - A) / nb;
}

// The texel of the last frame's history (`size` texels) that holds the
// surface at texel `pixel` (distance d, camera-space point X, normal n),
// and the distance that surface is expected at there
// (deepExpectedPreviousDistance); false where the reprojection leaves the
// history. vtkDeepRadiosityPass compiles its bounce input and temporal
// filter with DEEP_STILL_CAMERA for frames whose history is of this camera
// and grid: that texel is then `pixel` itself at distance d (where it was
// shaded), X and n are unused, and the compiler drops the arithmetic and
// fetches that made them.
bool deepLastFrameTexel(ivec2 pixel, float d, vec3 X, vec3 n, mat4 toPrevious,
  mat4 prevProjection, vec2 size, out ivec2 texel, out float expected)
{
#ifdef DEEP_STILL_CAMERA
  texel = pixel;
  expected = d;
  return deepShaded(texel);
#else
  float distance;
  expected = 0.0;
  if (!deepReproject(X, toPrevious, prevProjection, size, texel, distance))
  {
    return false;
  }
  expected = deepExpectedPreviousDistance(X, n, toPrevious, prevProjection, texel, size);
  return true;
#endif
}
