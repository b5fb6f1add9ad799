// Lab 7: the names that the lab's C++ (framebuffer_ops.cpp) and its shaders
// share, written once: plain #define lines, which both languages read alike.

// Vertex attribute locations: layout(location = ...) in quad.vert, and the
// locations of framebuffer_ops.cpp's vertex layout.
#define A_POSITION 0
#define A_UV 1

// The values of u_pattern: what faces.frag colours the open box by.
// framebuffer_ops.cpp's enum Pattern, bound to the parameter `pattern`,
// takes its values from these.
#define PATTERN_FACING 0
#define PATTERN_PRIMITIVE 1
#define PATTERN_SCREEN 2
#define PATTERN_OBJECT 3
