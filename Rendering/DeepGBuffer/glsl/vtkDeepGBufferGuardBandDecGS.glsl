// Deep G-buffer: the guard band's scale of clip x and y (section 3.5), for
// geometry shaders that project view-space positions themselves.
uniform vec2 deepGuardBandScale;
