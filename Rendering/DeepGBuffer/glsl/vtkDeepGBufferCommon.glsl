//=========================================================================
// Shared GLSL for the deep G-buffer passes. Substituted once into every
// shader that packs, unpacks or reconstructs G-buffer values.
//=========================================================================

// Octahedral normal encoding with 8 bits per component: "Oct16" in the
// paper's Table 1 (Cigolle et al., JCGT 2014). The octahedron coordinate
// p in [-1, 1]^2 is quantised to 255 symmetric levels k = round(127 p) + 127,
// stored as k / 255 in an 8-bit unsigned normalised target, so that p = 0
// (the axes) is exact.
vec2 deepSignNotZero(vec2 v)
{
  return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}

vec2 deepEncodeOct16(vec3 n)
{
  vec2 p = n.xy * (1.0 / (abs(n.x) + abs(n.y) + abs(n.z)));
  if (n.z < 0.0)
  {
    p = (1.0 - abs(p.yx)) * deepSignNotZero(p);
  }
  return (floor(clamp(p, -1.0, 1.0) * 127.0 + 0.5) + 127.0) / 255.0;
}

// The unit normal of the octahedron levels k (0..254 per axis).
vec3 deepNormalFromOct16Levels(vec2 k)
{
  vec2 p = (k - 127.0) / 127.0;
  vec3 n = vec3(p, 1.0 - abs(p.x) - abs(p.y));
  if (n.z < 0.0)
  {
    n.xy = (1.0 - abs(n.yx)) * deepSignNotZero(n.xy);
  }
  return normalize(n);
}

vec3 deepDecodeOct16(vec2 encoded)
{
  return deepNormalFromOct16Levels(floor(encoded * 255.0 + 0.5));
}

// Both levels of an Oct16 normal as one integer k.x + 256 k.y, exact in a
// float (a geometry key's normal, vtkDeepGeometryKeyFS), and back.
float deepPackOct16(vec2 encoded)
{
  vec2 k = floor(encoded * 255.0 + 0.5);
  return k.x + 256.0 * k.y;
}

// A geometry key's normal carries the surface's facing: 65536 is added for
// a back face (ALBEDO's alpha 0), still exact in a float.
float deepPackKeyNormal(vec2 encoded, bool backFace)
{
  return deepPackOct16(encoded) + (backFace ? 65536.0 : 0.0);
}

bool deepKeyBackFace(float levels)
{
  return levels >= 65536.0;
}

vec3 deepUnpackOct16(float levels)
{
  levels = deepKeyBackFace(levels) ? levels - 65536.0 : levels;
  float y = floor(levels * (1.0 / 256.0));
  return deepNormalFromOct16Levels(vec2(levels - 256.0 * y, y));
}

// Camera-space distance (positive in front of the camera) from clip-space
// coordinates. projZ holds the projection's third and fourth rows as
// (P22, P23, P32, P33): perspective has clip.w = P32 z + P33 with P32 = -1,
// parallel projection has clip.w = 1 and clip.z = P22 z + P23.
float deepDistanceFromClip(vec4 clip, vec4 projZ)
{
  if (projZ.z != 0.0)
  {
    return -(clip.w - projZ.w) / projZ.z;
  }
  return -(clip.z / clip.w - projZ.y) / projZ.x;
}

// The same for the fragment being shaded: gl_FragCoord.w is 1 / clip.w and
// gl_FragCoord.z is the window depth in [0, 1].
float deepDistanceFromFragCoord(vec4 fragCoord, vec4 projZ)
{
  float clipW = 1.0 / fragCoord.w;
  return deepDistanceFromClip(vec4(0.0, 0.0, (2.0 * fragCoord.z - 1.0) * clipW, clipW), projZ);
}

// The layer texel under frame texture coordinate `texCoord` (a full-screen
// quad over the renderer's viewport): layers of `size` texels hold the frame
// with a guard band of `guard` pixels on every side (paper section 3.5).
ivec2 deepFrameTexel(vec2 texCoord, ivec2 size, int guard)
{
  ivec2 frame = size - 2 * guard;
  return min(ivec2(texCoord * vec2(frame)), frame - 1) + guard;
}
