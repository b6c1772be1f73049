  // Deep G-buffer (after the uniform control flow): unlit props have no
  // shading normal; use the geometric normal of the position reconstructed
  // from the depth, facing the camera.
  vec4 deepNdc = vec4(gl_FragCoord.xy / deepViewportSize * 2.0 - 1.0,
    2.0 * gl_FragCoord.z - 1.0, 1.0);
  vec4 deepPositionVC = deepInverseProjection * deepNdc;
  deepPositionVC /= deepPositionVC.w;
  vec3 deepGeometricNormal = normalize(cross(dFdx(deepPositionVC.xyz), dFdy(deepPositionVC.xyz)));
  vec3 deepViewRay = deepProjectionZ.z != 0.0 ? deepPositionVC.xyz : vec3(0.0, 0.0, -1.0);
  if (dot(deepGeometricNormal, deepViewRay) > 0.0)
  {
    deepGeometricNormal = -deepGeometricNormal;
  }
