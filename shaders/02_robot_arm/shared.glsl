// Lab 2: the names that the lab's C++ (robot_arm.cpp) and its shaders share,
// written once: arm.vert pastes this file in with #include "shared.glsl", and
// robot_arm.cpp includes it as a C++ header.

// Vertex attribute location of the 2D position.
#define A_POSITION 0
