#version 430 core
// Lab 5, scene param_sphere: the lecture's parametric sphere on one quad
// patch, U = 2 pi u around the axis and V = pi v from pole to pole, radius 1.
// The poles lie on the y axis: v = 0 is the south pole (0, -1, 0), v = 1 the
// north pole; u = 0 and u = 1 meet on the seam at the back (-z).

layout(quads, ccw) in;

uniform mat4 u_view_projection;  // P * V (the model is the identity)

out vec3 e_normal;  // world space

const float kPi = 3.14159265358979;

void main() {
    float u = gl_TessCoord.x, v = gl_TessCoord.y;
    // BEGIN SOLUTION
    // STUDENT: // TODO: p = (-sin V sin U, -cos V, -sin V cos U) with U = 2 pi u, V = pi v;
    // STUDENT: // on a unit sphere the normal is the point itself.
    // STUDENT: vec3 p = vec3(u, v, 0.0);
    // STUDENT: e_normal = vec3(0.0, 0.0, 1.0);
    float U = 2.0 * kPi * u, V = kPi * v;
    vec3 p = vec3(-sin(V) * sin(U), -cos(V), -sin(V) * cos(U));
    e_normal = p;
    // END SOLUTION
    gl_Position = u_view_projection * vec4(p, 1.0);
}
