// Lab 12: the names that the lab's C++ (shadows.cpp, shadow_math.hpp) and its
// shaders share, written once: plain #define lines, which both languages read alike.

// Vertex attribute location: layout(location = ...) in scene.vert, and the
// location of shadows.cpp's vertex layout.
#define A_POSITION 0

// The values of u_fog_mode: which fog factor fog.frag computes. The enum Fog
// of shadow_math.hpp, bound to the parameter `fog`, takes its values from these.
#define FOG_NONE 0
#define FOG_LINEAR 1
#define FOG_EXP 2
#define FOG_EXP2 3
