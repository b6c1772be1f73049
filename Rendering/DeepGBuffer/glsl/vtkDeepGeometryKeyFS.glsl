//VTK::System::Dec

//=========================================================================
// The geometry key of the screen-space effects: per texel, two layers'
// camera-space distance and Oct16 normal in one RGBA32F texel,
//   (distance f, normal f, distance f + 1, normal f + 1), f = deepFirstLayer,
// each normal's two 8-bit levels and, where deepWithFacing is on, the
// surface's facing packed into one float (deepPackKeyNormal, exact). The
// gathers' and the filters' taps read a texel's geometry in one fetch
// instead of up to four (distance and normal per layer), the cost that
// dominates them on a CPU renderer (Documentation/performance.md).
// Distance 0: no surface (also for a layer from deepLayers on). The
// obscurance builds its rotated-grid pyramid from it
// (vtkDeepAmbientObscuranceMinifyFS).
//=========================================================================

in vec2 texCoord;

uniform sampler2DArray deepDistance;
uniform sampler2DArray deepNormal;
uniform sampler2DArray deepFacing; // ALBEDO: alpha 0 on back faces
uniform int deepWithFacing;        // 0: every surface packed as a front face
uniform int deepLayers;     // the G-buffer's
uniform int deepFirstLayer; // f
uniform ivec2 deepKeySize;

//VTK::DeepGBuffer::Common

//VTK::Output::Dec

void main()
{
  ivec2 texel = min(ivec2(texCoord * vec2(deepKeySize)), deepKeySize - 1);
  vec4 key = vec4(0.0);
  for (int k = 0; k < 2; ++k)
  {
    int j = deepFirstLayer + k;
    float d = j < deepLayers ? texelFetch(deepDistance, ivec3(texel, j), 0).r : 0.0;
    bool backFace =
      deepWithFacing != 0 && j < deepLayers && texelFetch(deepFacing, ivec3(texel, j), 0).a < 0.5;
    float n = j < deepLayers
      ? deepPackKeyNormal(texelFetch(deepNormal, ivec3(texel, j), 0).rg, backFace)
      : 0.0;
    if (k == 0)
    {
      key.xy = vec2(d, n);
    }
    else
    {
      key.zw = vec2(d, n);
    }
  }
  gl_FragData[0] = key;
  // The surface coverage, where a depth texture is attached to receive it
  // (vtkDeepScreenSpace::ScopedCoverageWrite): 0 where layer f holds a
  // surface, 1 where it holds none.
  gl_FragDepth = key.x > 0.0 ? 0.0 : 1.0;
}
