// Test header with an error on line 3 (tests/framework).
#define WHITE vec3(1.0)
const vec3 kGrey = undeclared_grey;
