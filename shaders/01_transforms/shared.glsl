// Lab 1: the names that the lab's C++ (transforms.cpp) and its shaders
// share, written once: transforms.vert pastes this file in with
// #include "shared.glsl", and transforms.cpp includes it as a C++ header.

// Vertex attribute location of the 2D position.
#define A_POSITION 0
