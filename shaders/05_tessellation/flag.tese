#version 430 core
// Lab 5, scene flag: the lecture's waving flag on one quad patch,
//   r(u, v) = (u W, v H, sin(K pi u + phase) D),
// with its normal from the cross product of the partial derivatives
// dr/du and dr/dv. gl_TessCoord.xy = (u, v), each in [0, 1].

layout(quads, ccw) in;

uniform mat4 u_view_projection;  // P * V (the model is the identity)
uniform float u_W, u_H;          // the flag's width and height
uniform float u_D;               // the wave's depth (amplitude)
uniform float u_K;               // half-waves across the flag
uniform float u_phase;           // radians

out vec3 e_normal;  // world space, unit length

const float kPi = 3.14159265358979;

void main() {
    float u = gl_TessCoord.x, v = gl_TessCoord.y;
    // BEGIN SOLUTION
    // STUDENT: // TODO: r(u, v), and the normal cross(dr/du, dr/dv), normalised.
    // STUDENT: vec3 r = vec3(u, v, 0.0);
    // STUDENT: e_normal = vec3(0.0, 0.0, 1.0);
    float angle = u_K * kPi * u + u_phase;
    vec3 r = vec3(u * u_W, v * u_H, sin(angle) * u_D);
    vec3 dr_du = vec3(u_W, 0.0, u_K * kPi * u_D * cos(angle));
    vec3 dr_dv = vec3(0.0, u_H, 0.0);
    e_normal = normalize(cross(dr_du, dr_dv));
    // END SOLUTION
    gl_Position = u_view_projection * vec4(r, 1.0);
}
