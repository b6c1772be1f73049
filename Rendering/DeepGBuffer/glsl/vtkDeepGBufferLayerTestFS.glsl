  // Deep G-buffer (before VTK's colouring
  // and lighting): the minimum-separation test of Listing 1 line 13 and
  // Listing 2 line 22. The oracle's own layer stores only its distance.
#ifdef DEEP_GBUFFER_ROUTED
  int deepLayer = deepLayerVSOutput;
#else
  int deepLayer = deepTargetLayer;
#endif
  bool deepLayerUsesOtherClip = (deepOtherClipLayerMask & (1 << deepLayer)) != 0;
  float deepDistance = deepDistanceFromFragCoord(gl_FragCoord,
    deepLayerUsesOtherClip ? deepOtherProjectionZ : deepProjectionZ);
  if (deepLayer == deepOracleLayerIndex)
  {
    gl_FragData[1] = vec4(0.0);
    gl_FragData[2] = vec4(0.0);
    gl_FragData[3] = vec4(deepDistance, 0.0, 0.0, 1.0);
    gl_FragData[4] = vec4(0.0);
#ifdef DEEP_GBUFFER_REFLECTIVITY
    gl_FragData[5] = vec4(0.0);
#endif
    return;
  }
#ifndef DEEP_GBUFFER_SINGLE_LAYER
  // With one layer these tests never pass their first condition; compiled
  // in, they would still cost llvmpipe, which runs both sides of a branch.
  if (deepLayer > 0 && deepCullBackFaces != 0 && gl_FrontFacing == false)
  {
    discard;
  }
  if (deepLayer > 0 && deepTestMode != DEEP_TEST_NONE)
  {
    // DEEP_TEST_SAME_PIXEL compares with the layer before at this pixel;
    // DEEP_TEST_REPROJECTED at this fragment's position in the other frame.
    vec2 deepTestPixel = gl_FragCoord.xy;
    float deepTestDistance = deepDistance;
    if (deepTestMode == DEEP_TEST_REPROJECTED)
    {
      vec4 previousClip = deepOtherClipVSOutput;
      if (previousClip.w <= 0.0)
      {
        discard;
      }
      deepTestPixel = (previousClip.xy / previousClip.w * 0.5 + 0.5) * deepViewportSize;
      deepTestDistance = deepDistanceFromClip(previousClip, deepOtherProjectionZ);
    }
    ivec2 deepTexel = ivec2(floor(deepTestPixel));
    if (any(lessThan(deepTexel, ivec2(0))) ||
      any(greaterThanEqual(deepTexel, ivec2(deepViewportSize))))
    {
      discard;
    }
    float deepOracle = texelFetch(deepHistoryDistance, ivec3(deepTexel, deepLayer - 1), 0).r;
    if (deepOracle <= 0.0 || !(deepTestDistance > deepOracle + deepMinimumSeparation))
    {
      discard;
    }
  }
#endif
