// Lab 4: the names that the lab's C++ (geometry.cpp) and its shaders share,
// written once. mesh.vert pastes this file in with #include "shared.glsl"
// (the framework's shader loader does that), and geometry.cpp includes it as
// a C++ header: plain #define lines only, which both languages read alike.

// Vertex attribute locations: layout(location = ...) in mesh.vert, and the
// locations of the vertex layout that geometry.cpp gives the icospheres.
#define A_POSITION 0
#define A_NORMAL 1
