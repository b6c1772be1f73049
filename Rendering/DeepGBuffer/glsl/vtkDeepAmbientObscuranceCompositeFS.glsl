//VTK::System::Dec

//=========================================================================
// COMPOSITE_MULTIPLY: outputs the filtered ambient visibility where layer 0
// has a surface; the pass blends it multiplicatively (dst.rgb *= AV) over
// the resolved layer-0 image. Empty pixels are discarded and keep the
// background.
//=========================================================================

in vec2 texCoord;

uniform sampler2D deepVisibility;
uniform sampler2DArray deepDistance;

//VTK::Output::Dec

void main()
{
  ivec2 size = textureSize(deepDistance, 0).xy;
  ivec2 pixel = min(ivec2(texCoord * vec2(size)), size - 1);
  if (!(texelFetch(deepDistance, ivec3(pixel, 0), 0).r > 0.0))
  {
    discard;
  }
  float av = clamp(texelFetch(deepVisibility, pixel, 0).r, 0.0, 1.0);
  gl_FragData[0] = vec4(av, av, av, 1.0);
}
