//=========================================================================
// Deep G-buffer declarations in VTK's fragment shader, with the depth
// peeling declarations. DEEP_GBUFFER_ROUTED: the geometry shader
// routes this fragment's triangle to layer deepLayerVSOutput; otherwise the
// layer being drawn is deepTargetLayer.
//=========================================================================
uniform int deepTestMode;
uniform int deepTargetLayer;
uniform int deepOracleLayerIndex;
uniform int deepOtherClipLayerMask;
uniform int deepCullBackFaces;
uniform int deepEmissive;
uniform float deepMinimumSeparation;
uniform vec4 deepProjectionZ;
uniform vec4 deepOtherProjectionZ;
uniform mat4 deepInverseProjection;
uniform vec2 deepViewportSize;
uniform sampler2DArray deepHistoryDistance;
in vec4 deepOtherClipVSOutput;
#ifdef DEEP_GBUFFER_ROUTED
flat in int deepLayerVSOutput;
#endif
