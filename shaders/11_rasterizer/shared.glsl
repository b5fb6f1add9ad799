// Lab 11: the names its C++ (rasterizer_lab.cpp) and its GLSL share.
#define A_POSITION 0
#define A_COLOR 1
// scene.frag's u_output: which colour it writes.
#define OUTPUT_SMOOTH 0
#define OUTPUT_AFFINE 1
#define OUTPUT_COUNT 2
// show.frag's u_view: which image it shows.
#define VIEW_CPU 0
#define VIEW_GL 1
#define VIEW_DIFFERENCE 2
