  // Deep G-buffer outputs (after texturing, where VTK's albedo is
  // final), paper Table 1: albedo, Oct16 normal, distance, the ambient part
  // of the radiance (0 for emissive props) and, with
  // DEEP_GBUFFER_REFLECTIVITY, the mirror reflectance. ALBEDO's alpha is 1
  // on a front face and 0 on a back face: where a layer enters or leaves a
  // solid (the obscurance's occupied stretches). The DEEP_GBUFFER_*
  // expressions name VTK's own shader variables for this mapper
  // (vtkDeepGBufferShaderTokens.h).
  gl_FragData[1] = vec4(clamp(DEEP_GBUFFER_ALBEDO, 0.0, 1.0), gl_FrontFacing ? 1.0 : 0.0);
  gl_FragData[2] = vec4(deepEncodeOct16(DEEP_GBUFFER_NORMAL), 0.0, 1.0);
  gl_FragData[3] = vec4(deepDistance, 0.0, 0.0, 1.0);
  gl_FragData[4] = vec4(deepEmissive != 0 ? vec3(0.0) : max(DEEP_GBUFFER_AMBIENT, vec3(0.0)), 1.0);
#ifdef DEEP_GBUFFER_REFLECTIVITY
  gl_FragData[5] = vec4(clamp(DEEP_GBUFFER_REFLECTIVITY, 0.0, 1.0), 1.0);
#endif
