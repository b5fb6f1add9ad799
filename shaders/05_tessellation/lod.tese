#version 430 core
// Lab 5, scene lod: places each generated vertex of a ground patch. The
// corners are flat (y = 0); the point between them, bilinear in (u, v), is
// lifted onto ridges that run along z, y = h(x) = A cos(pi x) with A = 0.5:
// crests at every even x (the patches' corners), valleys halfway between.
// The normal comes from the partial derivatives of (x, h(x), z).

layout(quads, ccw) in;

in vec3 c_position[];  // p0 (u, v) = (0, 0), p1 (1, 0), p2 (1, 1), p3 (0, 1)

uniform mat4 u_view_projection;  // P * V (the model is the identity)

out vec3 e_normal;  // world space, unit length

const float kPi = 3.14159265358979;
const float kRidge = 0.25;  // A, the ridges' height above the plane y = 0

void main() {
    float u = gl_TessCoord.x, v = gl_TessCoord.y;
    vec3 p = mix(mix(c_position[0], c_position[1], u), mix(c_position[3], c_position[2], u), v);
    p.y = kRidge * cos(kPi * p.x);
    // dr/dx = (1, -A pi sin(pi x), 0), dr/dz = (0, 0, 1); the normal is dr/dz x dr/dx, upwards.
    e_normal = normalize(vec3(kRidge * kPi * sin(kPi * p.x), 1.0, 0.0));
    gl_Position = u_view_projection * vec4(p, 1.0);
}
