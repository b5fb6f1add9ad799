#version 430 core
// Lab 5, scene triangle: the plain triangle patch. gl_TessCoord = (u, v, w)
// holds the barycentric coordinates of the generated vertex (u + v + w = 1),
// the weights of corners 0, 1 and 2. The spacing is declared in the
// spacing_*.tese linked beside this file.

layout(triangles, ccw) in;

in vec3 c_position[];  // the patch's corners, NDC (identity matrices)

uniform mat4 u_view_projection;  // identity in this scene

out vec3 e_normal;  // for wireframe.geom and shade.frag

void main() {
    vec3 p = gl_TessCoord.x * c_position[0] + gl_TessCoord.y * c_position[1] +
             gl_TessCoord.z * c_position[2];
    e_normal = vec3(0.0, 0.0, 1.0);
    gl_Position = u_view_projection * vec4(p, 1.0);
}
