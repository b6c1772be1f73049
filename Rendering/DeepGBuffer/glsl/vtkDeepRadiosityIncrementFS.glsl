//VTK::System::Dec

//=========================================================================
// The last bounce of a still image (vtkDeepRadiosityPass::
// ExtrapolateBounces): |E_k - E_k-1| of layer 0 at each texel of the
// gather's grid, E_k the filtered irradiance of this frame and E_k-1 the
// last frame's (0 without history). The camera is still, so both are of the
// same surface. The mean of the output (a mipmap's top level) over two
// frames gives the ratio of successive bounces; the magnitudes, not the
// signed increments, because the irradiance may approach its fixed point
// from below in some places and from above in others.
//=========================================================================

in vec2 texCoord;

uniform sampler2D deepInput0;   // filtered (E, confidence) of layer 0
uniform sampler2D deepHistory0; // the last frame's (E, distance) of layer 0
uniform int deepHasHistory;

//VTK::Output::Dec

void main()
{
  vec2 size = vec2(textureSize(deepInput0, 0));
  ivec2 texel = min(ivec2(texCoord * size), ivec2(size) - 1);
  vec3 E = texelFetch(deepInput0, texel, 0).rgb;
  vec3 last = deepHasHistory != 0 ? texelFetch(deepHistory0, texel, 0).rgb : vec3(0.0);
  gl_FragData[0] = vec4(abs(E - last), 1.0);
}
