  // Deep G-buffer (after the view-coordinate position): the guard band scales
  // clip x and y where VTK makes the clip position (mappers whose geometry
  // shader projects, DEEP_GBUFFER_GS_PROJECTS, scale each emitted vertex
  // instead); the other frame's clip position is passed on, and used as
  // this vertex's position when the layer is drawn at the other frame.
#ifndef DEEP_GBUFFER_GS_PROJECTS
  gl_Position.xy *= deepGuardBandScale;
#endif
  deepOtherClipVSOutput = deepOtherMCDC * vertexMC;
  if (deepVertexUsesOtherClip != 0)
  {
    gl_Position = deepOtherClipVSOutput;
  }
