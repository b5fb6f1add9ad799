#version 430 core
// Lab 7, scene faces: the open box coloured by what the rasterizer knows of
// each fragment, picked by u_pattern (shared.glsl):
//   PATTERN_FACING:    kOutside on front faces, kInside on back faces;
//   PATTERN_PRIMITIVE: grey (gl_PrimitiveID + 1) / 10 (10 triangles, ids 0-9);
//   PATTERN_SCREEN:    a checkerboard of 32 x 32-pixel squares in window
//                      coordinates: kLight where floor(x / 32) + floor(y / 32) is
//                      even, else kDark;
//   PATTERN_OBJECT:    the same colours over cubes of side 1/4 in object
//                      coordinates, centred on multiples of 1/4 so that no
//                      cube's side lies on a face of the box: kLight where
//                      c.x + c.y + c.z is even, c = floor(4 p + 0.5).

// PATTERN_*: the values of u_pattern, shared with framebuffer_ops.cpp.
#include "shared.glsl"

in vec3 v_object;  // the fragment's position in object coordinates

uniform int u_pattern;

layout(location = 0) out vec4 frag_color;

const vec3 kOutside = vec3(0.9, 0.5, 0.1), kInside = vec3(0.1, 0.5, 0.9);
const vec3 kLight = vec3(0.9), kDark = vec3(0.2);

vec3 checker(vec3 cell) { return mod(cell.x + cell.y + cell.z, 2.0) == 0.0 ? kLight : kDark; }

void main() {
    vec3 color = vec3(0.0);
    // BEGIN SOLUTION
    // STUDENT: // TODO: the colour u_pattern asks for, from gl_FrontFacing, gl_PrimitiveID,
    // STUDENT: // gl_FragCoord or v_object (checker() gives the checkerboard's colours)
    if (u_pattern == PATTERN_FACING) {
        color = gl_FrontFacing ? kOutside : kInside;
    } else if (u_pattern == PATTERN_PRIMITIVE) {
        color = vec3(float(gl_PrimitiveID + 1) / 10.0);
    } else if (u_pattern == PATTERN_SCREEN) {
        color = checker(vec3(floor(gl_FragCoord.xy / 32.0), 0.0));
    } else {
        color = checker(floor(4.0 * v_object + 0.5));
    }
    // END SOLUTION
    frag_color = vec4(color, 1.0);
}
