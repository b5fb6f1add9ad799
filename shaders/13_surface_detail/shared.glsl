// Lab 13: the names its C++ (surface_detail.cpp, scenes.cpp) and its GLSL share.
#define A_POSITION 0
#define A_NORMAL 1
#define A_TANGENT 2
#define A_BITANGENT 3
#define A_UV 4
#define A_COLOR 5
// bump.frag's u_normals: which normal lights the fragment.
#define NORMALS_BUMPED 0
#define NORMALS_INTERPOLATED 1
// envmap.frag's u_env: what the sphere shows.
#define ENV_FRESNEL 0
#define ENV_REFLECT 1
#define ENV_REFRACT 2
#define ENV_NORMAL 3
// flat.frag's u_output: the lit colour, or the triangle's number for the comparison.
#define OUTPUT_COLOR 0
#define OUTPUT_ID 1
// show.frag's u_view: which image it shows.
#define VIEW_CPU 0
#define VIEW_GL 1
#define VIEW_DIFFERENCE 2
