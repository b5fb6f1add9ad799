// Lab 3: the names that the lab's C++ (projection.cpp) and its shaders
// share, written once: projection.vert pastes this file in with
// #include "shared.glsl", and projection.cpp includes it as a C++ header.

// Vertex attribute location of the square's position.
#define A_POSITION 0
