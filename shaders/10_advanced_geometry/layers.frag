#version 430 core
// Lab 10, scene layers: the colours of the world inside the cube map, from
// the world position alone. A marker (a square at distance 1 on an axis) is
// (1, 0.2, 0.2) on +x, (0.2, 1, 1) on -x, and alike for y and z: its axis'
// channel 1 and the others 0.2 on the + side, the other way round on the -
// side. The room's walls (at distance 3) are 0.2 + 0.2 normalize(p).

in vec3 g_world;

layout(location = 0) out vec4 frag_color;

vec3 marker_color(vec3 p) {
    vec3 a = abs(p);
    int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    bool positive = p[axis] > 0.0;
    vec3 color = vec3(positive ? 0.2 : 1.0);
    color[axis] = positive ? 1.0 : 0.2;
    return color;
}

void main() {
    vec3 a = abs(g_world);
    bool wall = max(a.x, max(a.y, a.z)) > 2.0;
    frag_color = vec4(wall ? 0.2 + 0.2 * normalize(g_world) : marker_color(g_world), 1.0);
}
