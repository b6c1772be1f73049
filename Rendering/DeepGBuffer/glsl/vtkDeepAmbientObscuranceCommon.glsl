//=========================================================================
// Shared GLSL for the deep ambient obscurance shaders: camera-space
// position reconstruction from a deep G-buffer distance.
//=========================================================================

// Camera-space position of the surface at distance d (along -z, z = -d)
// seen through window pixel coordinate p (pixel centres at +0.5) of an
// image of size `size`. deepProjXY = (P00, P11, P02, P12),
// deepProjT = (P03, P13, P32, P33) of the projection the layers were
// rasterised with (perspective: P32 = -1, P33 = 0; parallel: P32 = 0,
// P33 = 1): clip.x = P00 x + P02 z + P03, clip.w = P32 z + P33.
uniform vec4 deepProjXY;
uniform vec4 deepProjT;

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
