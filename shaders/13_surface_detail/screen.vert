#version 430 core
// Lab 13, scenes envmap and raycast: one triangle covering the viewport, with texture
// coordinates that run from 0 to 1 across it.
out vec2 v_uv;

void main() {
    const vec2 corners[3] = vec2[3](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
    gl_Position = vec4(corners[gl_VertexID], 0.0, 1.0);
    v_uv = corners[gl_VertexID] * 0.5 + 0.5;
}
