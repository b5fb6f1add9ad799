// Test shader: each invocation doubles one value of a storage buffer and
// adds its work group's number (tests/framework).
#version 430 core
layout(local_size_x = 4) in;
layout(std430, binding = 0) buffer Values {
    float values[];
};
uniform uint u_count;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= u_count) return;
    values[i] = 2.0 * values[i] + float(gl_WorkGroupID.x);
}
