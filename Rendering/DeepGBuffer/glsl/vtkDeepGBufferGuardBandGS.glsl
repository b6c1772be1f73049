gl_Position.xy *= deepGuardBandScale;
