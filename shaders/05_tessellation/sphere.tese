#version 430 core
// Lab 5, scene sphere: each face of the icosahedron is a patch; every vertex
// the tessellator generates on it is pushed out onto the unit sphere, the
// lecture's normalize(p0 + p1 + p2) with the barycentric weights (u, v, w)
// of gl_TessCoord. The finer the levels, the rounder the sphere.

layout(triangles, ccw) in;

in vec3 c_position[];  // the face's corners, on the unit sphere

uniform mat4 u_view_projection;  // P * V (the model is the identity)

out vec3 e_normal;  // world space

void main() {
    vec3 flat_point = gl_TessCoord.x * c_position[0] + gl_TessCoord.y * c_position[1] +
                      gl_TessCoord.z * c_position[2];
    // BEGIN SOLUTION
    // STUDENT: // TODO: move the point onto the unit sphere; there, the normal is the point.
    // STUDENT: vec3 p = flat_point;
    // STUDENT: e_normal = normalize(cross(c_position[1] - c_position[0], c_position[2] - c_position[0]));
    vec3 p = normalize(flat_point);
    e_normal = p;
    // END SOLUTION
    gl_Position = u_view_projection * vec4(p, 1.0);
}
