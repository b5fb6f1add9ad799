// Test shader: transform feedback captures each value doubled and its index,
// with nothing rasterized (tests/framework).
#version 430 core
layout(location = 0) in vec3 a_value;
out vec3 v_doubled;
out float v_index;

void main() {
    v_doubled = 2.0 * a_value;
    v_index = float(gl_VertexID);
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
