//VTK::System::Dec

//=========================================================================
// Temporal accumulation with reprojection of the filtered ambient
// visibility. Writes (AV, d): AV = mix(AV_now, AV_history, alpha) where the
// history is valid, else AV_now; d is layer 0's distance (0 = empty), kept
// as the next frame's history distance.
// Reprojection: camera-space X from the current distance and projection,
// to the previous camera (deepToPrevious = V_prev * inverse(V_now)), to the
// previous clip space (deepPrevProjection), to the nearest previous texel.
// Rejected (AV_now) when the point is behind the previous camera or
// outside the previous image, when the previous distance there is 0, or
// when |d_prev - d_reprojected| > deepTolerance * d_reprojected.
//=========================================================================

in vec2 texCoord;

uniform sampler2D deepInput;        // AV_now (R32F, filtered)
uniform sampler2D deepHistory;      // (AV, d) of the previous frame (RG32F)
uniform sampler2DArray deepDistance;
uniform mat4 deepToPrevious;        // current camera -> previous camera
uniform mat4 deepPrevProjection;    // previous camera -> previous clip
uniform float deepAlpha;            // history weight
uniform int deepHasHistory;
uniform float deepTolerance;        // relative distance tolerance

//VTK::DeepGBuffer::Common

//VTK::DeepScreenSpace::Common

//VTK::Output::Dec

void main()
{
  vec2 size = vec2(textureSize(deepDistance, 0).xy);
  ivec2 pixel = min(ivec2(texCoord * size), ivec2(size) - 1);
  float now = texelFetch(deepInput, pixel, 0).r;
  float d = texelFetch(deepDistance, ivec3(pixel, 0), 0).r;
  if (!(d > 0.0))
  {
    gl_FragData[0] = vec4(now, 0.0, 0.0, 1.0);
    return;
  }
  float av = now;
  if (deepHasHistory != 0)
  {
    vec3 X = deepPositionFromDistance(vec2(pixel) + 0.5, size, d);
    ivec2 texel;
    float dr; // reprojected distance
    if (deepReproject(X, deepToPrevious, deepPrevProjection, size, texel, dr))
    {
      vec2 history = texelFetch(deepHistory, texel, 0).rg;
      if (history.g > 0.0 && abs(history.g - dr) <= deepTolerance * dr)
      {
        av = mix(now, history.r, deepAlpha);
      }
    }
  }
  gl_FragData[0] = vec4(clamp(av, 0.0, 1.0), d, 0.0, 1.0);
}
