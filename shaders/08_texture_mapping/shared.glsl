// Lab 8: the names that the lab's C++ (texture_mapping.cpp) and its shaders
// share, written once: plain #define lines, which both languages read alike.

// Vertex attribute locations: layout(location = ...) in textured.vert, and
// the locations of the lab's vertex layouts.
#define A_POSITION 0
#define A_UV 1
#define A_NORMAL 2

// The values of u_mapping: where sphere.frag takes (s, t) from.
// texture_mapping.cpp's enum Mapping, bound to the parameter `mapping`, takes
// its values from these.
#define MAPPING_VERTEX 0
#define MAPPING_PLANAR 1
#define MAPPING_CYLINDRICAL 2
#define MAPPING_SPHERICAL 3

// The values of u_maps: what quad.frag shows in scene lightmap.
#define MAPS_BASE 0
#define MAPS_LIGHT 1
#define MAPS_MODULATE 2
