#version 430 core
// Lab 6, scenes triangle and plane: the same vertex value, interpolated
// three ways; u_qualifier picks the one shown. The triangle shows it as a
// colour, the plane as a checkerboard over the texture coordinates (u, v).

// The qualifiers are written on both sides, here and in interpolate.vert.
// BEGIN SOLUTION
// STUDENT: in vec3 v_smooth;         // TODO: perspective-correct (the default)
// STUDENT: in vec3 v_noperspective;  // TODO: linear in window coordinates
// STUDENT: in vec3 v_flat;           // TODO: the provoking vertex's value, not interpolated
// Perspective-correct: linear on the triangle in the world, which in window
// coordinates means interpolating value / w and 1 / w and dividing.
smooth in vec3 v_smooth;
// Linear in window coordinates: the screen-space barycentrics, no 1 / w.
noperspective in vec3 v_noperspective;
// Not interpolated: the provoking vertex's value on the whole triangle.
flat in vec3 v_flat;
// END SOLUTION

// QUALIFIER_SMOOTH, QUALIFIER_NOPERSPECTIVE, QUALIFIER_FLAT: the values of
// u_qualifier, shared with interpolation.cpp.
#include "shared.glsl"

uniform int u_qualifier;      // which input is shown: a QUALIFIER_* value
uniform bool u_checkerboard;  // false: the value is a colour; true: it is (u, v, 0)
uniform float u_checks;       // cells along u and along v

layout(location = 0) out vec4 frag_color;

const vec3 kLight = vec3(0.9), kDark = vec3(0.1);

void main() {
    vec3 value = u_qualifier == QUALIFIER_SMOOTH          ? v_smooth
               : u_qualifier == QUALIFIER_NOPERSPECTIVE ? v_noperspective
                                                        : v_flat;
    if (u_checkerboard) {
        vec2 cell = floor(value.xy * u_checks);
        frag_color = vec4(mod(cell.x + cell.y, 2.0) == 0.0 ? kLight : kDark, 1.0);
    } else {
        frag_color = vec4(value, 1.0);
    }
}
