//VTK::System::Dec

//=========================================================================
// One layer of the reduced G-buffer of deep screen-space radiosity gathered
// on a reduced grid (vtkDeepRadiosityPass::SetResolutionDivisor D > 1):
// reduced texel q holds the distance, normal and albedo of layer texel D q
// (clamped), unchanged, for the stages that run on the grid (filters,
// temporal filter, upsampling). A regular grid (not an average, which
// would invent surfaces at silhouettes); the projection the stages use is
// corrected for the texel's position (vtkDeepScreenSpace::ReducedProjection),
// so positions are exact.
//=========================================================================

in vec2 texCoord;

uniform sampler2DArray deepDistance;
uniform sampler2DArray deepNormal;
uniform sampler2DArray deepAlbedo;
uniform int deepDivisor;
uniform int deepLayer;
uniform ivec2 deepReducedSize;

//VTK::Output::Dec

void main()
{
  ivec2 q = min(ivec2(texCoord * vec2(deepReducedSize)), deepReducedSize - 1);
  ivec3 source = ivec3(min(q * deepDivisor, textureSize(deepDistance, 0).xy - 1), deepLayer);
  gl_FragData[0] = vec4(texelFetch(deepDistance, source, 0).r, 0.0, 0.0, 1.0);
  gl_FragData[1] = texelFetch(deepNormal, source, 0);
  gl_FragData[2] = texelFetch(deepAlbedo, source, 0);
}
