#version 430 core
// Lab 3: takes each vertex of the square from object space to clip space.
// u_model (M) places the square in the world, u_view (V = lookAt) moves the
// world into the camera's frame, u_projection (P) maps the view volume to
// clip space; GL then divides by w (NDC) and applies the viewport (window).

// A_POSITION: the attribute location, shared with projection.cpp.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;

uniform mat4 u_model;
uniform mat4 u_view;
uniform mat4 u_projection;

void main() {
    // BEGIN SOLUTION
    // STUDENT: // TODO: this is the last deck's row-vector formula p' = p M V P copied as it
    // STUDENT: // stands; here vectors are columns and the matrices act from the right.
    // STUDENT: gl_Position = vec4(a_position, 1.0) * u_model * u_view * u_projection;
    gl_Position = u_projection * u_view * u_model * vec4(a_position, 1.0);
    // END SOLUTION
}
