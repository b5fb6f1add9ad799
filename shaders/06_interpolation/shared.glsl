// Lab 6: the names that the lab's C++ (interpolation.cpp) and its shaders
// share, written once. The shaders paste this file in with
// #include "shared.glsl" (the framework's shader loader does that), and
// interpolation.cpp includes it as a C++ header: plain #define lines only,
// which both languages read alike.

// Vertex attribute locations: layout(location = ...) in interpolate.vert and
// shading.vert, and the locations of interpolation.cpp's vertex layouts.
#define A_POSITION 0  // both
#define A_VALUE 1     // interpolate.vert: a colour, or the floor's (u, v, 0)
#define A_NORMAL 1    // shading.vert

// The values of u_qualifier: which of its three inputs interpolate.frag
// shows. interpolation.cpp's enum Qualifier, bound to the parameter
// `qualifier`, takes its values from these.
#define QUALIFIER_SMOOTH 0
#define QUALIFIER_NOPERSPECTIVE 1
#define QUALIFIER_FLAT 2

// The values of u_shading: how shading.frag colours the sphere.
// interpolation.cpp's enum Shading, bound to the parameter `shading`, takes
// its values from these.
#define SHADING_GOURAUD 0  // the colour lit per vertex, interpolated
#define SHADING_PHONG 1    // lit per pixel
#define SHADING_TOON 2     // three tones and an outline
