//=========================================================================
// Deep G-buffer declarations in VTK's vertex shader (after the camera declarations).
// deepOtherMCDC: model to clip of the other frame the oracle needs (the
// previous frame for REPROJECT and DELAY, the predicted next frame for
// PREDICT); deepGuardBandScale widens the frustum by the guard band
// (section 3.5).
//=========================================================================
uniform mat4 deepOtherMCDC;
uniform int deepVertexUsesOtherClip;
uniform vec2 deepGuardBandScale;
out vec4 deepOtherClipVSOutput;
