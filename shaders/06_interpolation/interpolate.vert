#version 430 core
// Lab 6, scenes triangle and plane: hands each vertex's value (a colour, or
// the floor's texture coordinates (u, v, 0)) to the rasterizer three times,
// once for each way interpolate.frag asks it to be interpolated.

// A_POSITION and A_VALUE: the attribute locations, shared with
// interpolation.cpp.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;
layout(location = A_VALUE) in vec3 a_value;

uniform mat4 u_mvp;  // the identity (triangle) or P * V (plane)

// The same three qualifiers as the inputs of interpolate.frag: in GLSL 4.30
// an output and the input of the same name must agree on their
// interpolation qualifier (even smooth against none), or the program fails
// to link (section 4.5; GLSL 4.40 dropped the rule).
// BEGIN SOLUTION
// STUDENT: out vec3 v_smooth;         // TODO: the qualifiers, as in interpolate.frag
// STUDENT: out vec3 v_noperspective;
// STUDENT: out vec3 v_flat;
smooth out vec3 v_smooth;
noperspective out vec3 v_noperspective;
flat out vec3 v_flat;
// END SOLUTION

void main() {
    v_smooth = a_value;
    v_noperspective = a_value;
    v_flat = a_value;
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
