// Test header (tests/framework): names shared by test_wrapper.cpp's C++ and
// included.vert, pasted in by the loader's #include.
#define A_POSITION 0
#define A_COLOR 1
