//VTK::System::Dec

//=========================================================================
// Deep G-buffer layer routing (Mara et al. 2016, Listing 2, lines 1-6).
// Each triangle is emitted once per layer selected by deepEmitMask, with
// gl_Layer selecting the slice of the 2D array render targets. Layers whose
// bit is set in deepOtherClipLayerMask are rasterised at the other frame's
// position (DELAY: the previous frame; PREDICT: the predicted next frame).
// The //VTK:: tags let the mapper pass its varyings through, as in VTK's
// own geometry shader templates (index i is the input vertex).
//=========================================================================

//VTK::PositionVC::Dec
//VTK::PrimID::Dec
//VTK::Color::Dec
//VTK::Normal::Dec
//VTK::Light::Dec
//VTK::TCoord::Dec
//VTK::Picking::Dec
//VTK::DepthPeeling::Dec
//VTK::Clip::Dec
//VTK::Output::Dec

layout(triangles) in;
layout(triangle_strip, max_vertices = DEEP_GBUFFER_MAX_VERTICES) out;

uniform int deepEmitMask;
uniform int deepOtherClipLayerMask;
uniform int deepCullBackFaces;

in vec4 deepOtherClipVSOutput[];
out vec4 deepOtherClipGSOutput;
flat out int deepLayerGSOutput;

// True when the three clip-space vertices lie outside one frustum plane:
// the triangle covers no pixel in any layer that uses these positions.
bool deepOutsideFrustum(vec4 a, vec4 b, vec4 c)
{
  return (a.x > a.w && b.x > b.w && c.x > c.w) || (a.x < -a.w && b.x < -b.w && c.x < -c.w) ||
    (a.y > a.w && b.y > b.w && c.y > c.w) || (a.y < -a.w && b.y < -b.w && c.y < -c.w) ||
    (a.z > a.w && b.z > b.w && c.z > c.w) || (a.z < -a.w && b.z < -b.w && c.z < -c.w);
}

// True for a back-facing triangle (counter-clockwise front faces) whose
// vertices are all in front of the camera, where the winding is defined.
bool deepBackFacing(vec4 a, vec4 b, vec4 c)
{
  if (a.w <= 0.0 || b.w <= 0.0 || c.w <= 0.0)
  {
    return false;
  }
  vec2 pa = a.xy / a.w, pb = b.xy / b.w, pc = c.xy / c.w;
  return (pb.x - pa.x) * (pc.y - pa.y) - (pc.x - pa.x) * (pb.y - pa.y) < 0.0;
}

void main()
{
  // Rasterising nothing is the cheapest work a geometry shader can save,
  // which matters most on CPU renderers where it runs per triangle.
  bool currentOutside =
    deepOutsideFrustum(gl_in[0].gl_Position, gl_in[1].gl_Position, gl_in[2].gl_Position);
  bool otherOutside = deepOutsideFrustum(
    deepOtherClipVSOutput[0], deepOtherClipVSOutput[1], deepOtherClipVSOutput[2]);
  bool currentBackFacing =
    deepBackFacing(gl_in[0].gl_Position, gl_in[1].gl_Position, gl_in[2].gl_Position);
  bool otherBackFacing =
    deepBackFacing(deepOtherClipVSOutput[0], deepOtherClipVSOutput[1], deepOtherClipVSOutput[2]);
  for (int layer = 0; layer < DEEP_GBUFFER_LAYER_SLOTS; ++layer)
  {
    bool useOtherClip = (deepOtherClipLayerMask & (1 << layer)) != 0;
    // Deeper layers keep front faces only (the fragment shader applies the
    // same rule to props drawn without this shader). The oracle layer of
    // PREDICT and DELAY stands for layer 0 and keeps everything.
    bool culled = layer > 0 && layer < DEEP_GBUFFER_DISPLAYED_LAYERS && deepCullBackFaces != 0 &&
      (useOtherClip ? otherBackFacing : currentBackFacing);
    // One condition, not a `continue` per test: a CPU renderer (Mesa
    // llvmpipe) counted 3 % fewer instructions for the layers this way.
    if ((deepEmitMask & (1 << layer)) != 0 && !(useOtherClip ? otherOutside : currentOutside) &&
      !culled)
    {
      for (int i = 0; i < 3; ++i)
      {
        //VTK::PrimID::Impl
        //VTK::Clip::Impl
        //VTK::Color::Impl
        //VTK::Normal::Impl
        //VTK::Light::Impl
        //VTK::TCoord::Impl
        //VTK::DepthPeeling::Impl
        //VTK::Picking::Impl
        //VTK::PositionVC::Impl
        deepOtherClipGSOutput = deepOtherClipVSOutput[i];
        deepLayerGSOutput = layer;
        gl_Layer = layer;
        gl_Position = useOtherClip ? deepOtherClipVSOutput[i] : gl_in[i].gl_Position;
        EmitVertex();
      }
      EndPrimitive();
    }
  }
}
