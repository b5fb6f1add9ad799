// Lab 10: the names that the lab's C++ and its shaders share, written once:
// plain #define lines, which both languages read alike.

// Vertex attribute locations: every mesh's position (grid.vert's quad
// corner), an instance's colour (grid.vert, one per instance), the sphere's
// normal (sphere.vert).
#define A_POSITION 0
#define A_COLOR 1
#define A_NORMAL 1

// The texture unit the cube map is read from (cross.frag).
#define T_CUBE 0
