// Lab 5: the names that the lab's C++ (tessellation.cpp) and its shaders
// share, written once. patch.vert and shade.frag paste this file in with
// #include "shared.glsl" (the framework's shader loader does that), and
// tessellation.cpp includes it as a C++ header: plain #define lines only,
// which both languages read alike.

// Vertex attribute location: layout(location = ...) in patch.vert, and the
// location of the vertex layout that tessellation.cpp gives the patches.
#define A_POSITION 0

// The values of u_shading: how shade.frag colours a fragment that is not on
// an edge. tessellation.cpp's enum Shading takes its values from these.
#define SHADING_FILL 0     // the fill colour u_color (scene triangle)
#define SHADING_LAMBERT 1  // u_color times Lambert's diffuse term
#define SHADING_NORMAL 2   // the unit normal n as the colour 0.5 n + 0.5 (show=normals)
