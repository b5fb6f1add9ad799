#version 430 core
// Lab 9, scenes subdivide and block: the colour lit by one directional light,
// color (ambient + (1 - ambient) max(N.L, 0)), from the uniform block.

// B_SCENE: shared with the lab.
#include "shared.glsl"

layout(std140, binding = B_SCENE) uniform SceneBlock {
    mat4 mvp;
    mat3 normal_matrix;
    vec3 light;
    float ambient;
    vec4 color;
};

in vec3 v_normal;

layout(location = 0) out vec4 frag_color;

void main() {
    float diffuse = max(dot(normalize(v_normal), light), 0.0);
    frag_color = vec4(color.rgb * (ambient + (1.0 - ambient) * diffuse), 1.0);
}
