// Constants shared by several passes (PI comes from atmosphere/functions.glsl).

// Material ids stored in the G-buffer (material.r * 255).
const int MATERIAL_NONE = 0;    // nothing rendered: sky / space
const int MATERIAL_GROUND = 1;  // solid planet surface
