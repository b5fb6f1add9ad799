// Lab 0: the names that the lab's C++ (pipeline.cpp) and its shaders share,
// written once. pipeline.vert pastes this file in with #include "shared.glsl"
// (the framework's shader loader does that), and pipeline.cpp includes it as a
// C++ header: plain #define lines only, which both languages read alike.

// Vertex attribute locations: layout(location = ...) in pipeline.vert, and
// the first argument of glVertexAttribPointer in pipeline.cpp.
#define A_POSITION 0
#define A_COLOR 1
