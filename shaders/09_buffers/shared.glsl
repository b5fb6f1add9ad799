// Lab 9: the names that the lab's C++ (buffers.cpp) and its shaders share,
// written once: plain #define lines, which both languages read alike.

// Vertex attribute locations: a particle's position and velocity
// (advance.vert, points.vert), a sphere's position and normal (sphere.vert,
// subdivide.vert).
#define A_POSITION 0
#define A_VELOCITY 1
#define A_NORMAL 1

// The storage buffer binding advance.comp reads and writes its particles at.
#define B_PARTICLES 0

// The uniform buffer binding of the block SceneBlock (sphere.vert, sphere.frag).
#define B_SCENE 0
