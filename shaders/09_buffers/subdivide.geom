#version 430 core
// Lab 9, scene subdivide: one triangle (a, b, c) of the unit sphere in, four
// out, each captured by transform feedback as three vertices (g_position),
// in the sheet's order: (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca),
// where ab = normalize(a + b) is the midpoint of a-b pushed out to the sphere.

layout(triangles) in;
layout(triangle_strip, max_vertices = 12) out;

in vec3 v_position[];

out vec3 g_position;

void emit(vec3 p) {
    g_position = p;
    gl_Position = vec4(p, 1.0);
    EmitVertex();
}

// One triangle of its own: three vertices, then the strip ends.
void triangle(vec3 p, vec3 q, vec3 r) {
    emit(p);
    emit(q);
    emit(r);
    EndPrimitive();
}

void main() {
    vec3 a = v_position[0], b = v_position[1], c = v_position[2];
    // BEGIN SOLUTION
    // STUDENT: triangle(a, b, c);  // TODO: the four triangles, midpoints pushed out to the sphere
    vec3 ab = normalize(a + b), bc = normalize(b + c), ca = normalize(c + a);
    triangle(a, ab, ca);
    triangle(ab, b, bc);
    triangle(ca, bc, c);
    triangle(ab, bc, ca);
    // END SOLUTION
}
