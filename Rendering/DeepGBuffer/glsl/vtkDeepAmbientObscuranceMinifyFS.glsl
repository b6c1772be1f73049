//VTK::System::Dec

//=========================================================================
// One level of the MIP pyramid of one slice of the geometry key
// (vtkDeepGeometryKeyFS: two layers' distances and normals), Mara et al.
// 2016, section 3.4, after McGuire, Mara and Luebke, "Scalable Ambient
// Obscurance", HPG 2012: rotated-grid downsampling. Level m + 1 texel
// (x, y) takes level m texel
//   (2x + (y & 1), 2y + (x & 1)), clamped to level m's size -- SAO's
//   SAO_minify.pix (`ssP * 2 + ivec2(ssP.y & 1, ssP.x & 1)`). One texel is
// selected, never an average, so 0 (empty) stays 0 and every value is a
// true surface's distance and normal. The pass sets deepSource's base and max level to
// the level read, so lod 0 here is that level.
//=========================================================================

in vec2 texCoord;

uniform sampler2DArray deepSource;
uniform int deepLayer; // the slice
uniform ivec2 deepTargetSize; // size of the level written

//VTK::Output::Dec

void main()
{
  ivec2 p = min(ivec2(texCoord * vec2(deepTargetSize)), deepTargetSize - 1);
  ivec2 sourceSize = textureSize(deepSource, 0).xy;
  ivec2 s = clamp(2 * p + ivec2(p.y & 1, p.x & 1), ivec2(0), sourceSize - 1);
  gl_FragData[0] = texelFetch(deepSource, ivec3(s, deepLayer), 0);
}
