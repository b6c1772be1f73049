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

in vec4 deepOtherClipVSOutput[];
out vec4 deepOtherClipGSOutput;
flat out int deepLayerGSOutput;

void main()
{
  for (int layer = 0; layer < DEEP_GBUFFER_LAYER_SLOTS; ++layer)
  {
    if ((deepEmitMask & (1 << layer)) == 0)
    {
      continue;
    }
    bool useOtherClip = (deepOtherClipLayerMask & (1 << layer)) != 0;
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
