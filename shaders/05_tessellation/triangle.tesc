#version 430 core
// Lab 5: the control shader of the triangle patches (scenes triangle and
// sphere). It runs once per output control point, gl_InvocationID 0, 1, 2,
// and passes its point on; the levels belong to the whole patch, so one
// invocation sets them (set_levels() in levels.tesc).

layout(vertices = 3) out;

in vec3 v_position[];   // the patch's corners, from patch.vert
out vec3 c_position[];  // the same corners, for the evaluation shader

void set_levels();

void main() {
    c_position[gl_InvocationID] = v_position[gl_InvocationID];
    if (gl_InvocationID == 0) set_levels();
}
