// One triangle that covers the screen; passes NDC to the fragment stage.
out vec2 vNdc;

void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0 - 1.0;  // (-1,-1) (3,-1) (-1,3)
    vNdc = p;
    gl_Position = vec4(p, 0.0, 1.0);
}
