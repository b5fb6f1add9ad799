// Lab 11's parameters and scenes; every number is one of
// labs/11_rasterizer/README.md, The scenes.
#include "scenes.hpp"

#include <utility>

namespace rasterizer {

namespace {

const glm::vec3 kWhite{1, 1, 1}, kRed{1, 0, 0}, kGreen{0, 1, 0}, kBlue{0, 0, 1};
const glm::vec3 kYellow{1, 1, 0};

// A window vertex as GL's clip space holds it: NDC = 2 * window / kGrid - 1
// and z_ndc = 2 z - 1, all multiplied by w.
ClipVertex clip_from_window(const WindowVertex& v) {
    const glm::vec3 ndc{2.0f * v.window.x / kGrid - 1.0f, 2.0f * v.window.y / kGrid - 1.0f,
                        2.0f * v.window.z - 1.0f};
    return {glm::vec4(ndc * v.w, v.w), v.color};
}

// scene=mesh: 8 triangles around the pixel centre (16.5, 16.5), over the
// square [4, 28]^2, one colour each.
std::vector<WindowVertex> mesh_triangles(Winding winding) {
    const glm::vec2 ring[8] = {{4, 4},   {16.5f, 4},  {28, 4}, {28, 16.5f},
                               {28, 28}, {16.5f, 28}, {4, 28}, {4, 16.5f}};
    const glm::vec3 colors[8] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1},    {1, 1, 0},
                                 {1, 0, 1}, {0, 1, 1}, {1, 0.5f, 0}, {0.5f, 0.5f, 1}};
    std::vector<WindowVertex> out;
    for (int i = 0; i < 8; ++i) {
        WindowVertex t[3] = {{{16.5f, 16.5f, 0.5f}, 1.0f, colors[i]},
                             {{ring[i], 0.5f}, 1.0f, colors[i]},
                             {{ring[(i + 1) % 8], 0.5f}, 1.0f, colors[i]}};
        if (winding == Winding::Cw) std::swap(t[1], t[2]);
        out.insert(out.end(), t, t + 3);
    }
    return out;
}

// scene=shading: triangle A with a red, a green and a blue corner and
// different w, then the yellow triangle B, which crosses A in depth. No edge
// passes through a pixel centre, so GL covers the same pixels on any GPU.
std::vector<WindowVertex> shading_triangles() {
    return {{{2, 2, 0.2f}, 1.0f, kRed},      {{30, 2, 0.2f}, 4.0f, kGreen},
            {{2, 29, 0.8f}, 1.0f, kBlue},    {{8, 8, 0.9f}, 1.0f, kYellow},
            {{30, 13, 0.1f}, 1.0f, kYellow}, {{12, 29, 0.1f}, 1.0f, kYellow}};
}

// scene=clipping: one triangle in clip space with one or two corners behind
// the near plane (z < -w).
std::vector<ClipVertex> clipping_triangle(Behind behind) {
    const ClipVertex front0{{-0.8f, -0.8f, 0.0f, 1.0f}, kRed};
    if (behind == Behind::One)
        return {front0, {{1.6f, -1.6f, 0.0f, 2.0f}, kGreen}, {{0.0f, 0.8f, -3.0f, 1.0f}, kBlue}};
    return {front0, {{0.8f, -0.8f, -3.0f, 1.0f}, kGreen}, {{0.0f, 0.8f, -3.0f, 1.0f}, kBlue}};
}

}  // namespace

std::vector<fw::Param> params() {
    return {
        fw::Param::choice(kScene, kScenes, Scene::Mesh)
            .help("lines: 8 segments; mesh: 8 triangles sharing edges; shading: colour and "
                  "depth; clipping: a triangle crossing the near plane")
            .key('S'),
        fw::Param::choice(kView, kViews, View::Split)
            .help("split: the CPU image left, GL's right; cpu; gl; difference: |cpu - gl|")
            .key('V'),
        fw::Param::choice(kAlgorithm, kAlgorithms, Algorithm::Bresenham)
            .help("the CPU's algorithm: dda or bresenham for the lines; scanline fills the "
                  "triangles span by span (mesh, shading), the others by edge functions")
            .key('A'),
        fw::Param::boolean(kReverse, false)
            .help("draw each segment from its end to its start (lines)")
            .key('E'),
        fw::Param::choice(kWinding, kWindings, Winding::Ccw)
            .help("the triangles' vertex order on screen (mesh)")
            .key('W'),
        fw::Param::choice(kInterpolation, kInterpolations, Interpolation::Perspective)
            .help("perspective-correct (smooth) or affine (noperspective) colour (shading)")
            .key('I'),
        fw::Param::boolean(kDepthTest, true).help("GL_LESS depth test (shading)").key('D'),
        fw::Param::choice(kBehind, kBehinds, Behind::One)
            .help("how many corners lie behind the near plane (clipping)")
            .key('B'),
    };
}

std::vector<Line> scene_lines(bool reverse) {
    std::vector<Line> lines = {{{1, 1}, {12, 5}},    {{30, 1}, {19, 6}}, {{12, 30}, {1, 27}},
                               {{19, 30}, {30, 26}}, {{2, 9}, {7, 20}},  {{10, 20}, {13, 9}},
                               {{22, 9}, {18, 20}},  {{29, 20}, {24, 9}}};
    if (reverse)
        for (Line& l : lines) std::swap(l.a, l.b);
    return lines;
}

GlScene gl_scene(const fw::ParamValues& p) {
    GlScene out{GL_TRIANGLES, {}};
    const auto add_window = [&out](const std::vector<WindowVertex>& vs) {
        for (const WindowVertex& v : vs) out.vertices.push_back(clip_from_window(v));
    };
    switch (p[kScene]) {
        case Scene::Lines:
            out.mode = GL_LINES;
            for (const Line& l : scene_lines(p[kReverse]))
                for (const glm::ivec2 end : {l.a, l.b})
                    out.vertices.push_back(
                        clip_from_window({{glm::vec2(end) + 0.5f, 0.5f}, 1.0f, kWhite}));
            break;
        case Scene::Mesh:
            add_window(mesh_triangles(p[kWinding]));
            break;
        case Scene::Shading:
            add_window(shading_triangles());
            break;
        case Scene::Clipping:
            out.vertices = clipping_triangle(p[kBehind]);
            break;
    }
    return out;
}

CpuScene cpu_scene(const fw::ParamValues& p) {
    CpuScene out;
    switch (p[kScene]) {
        case Scene::Lines:
            for (const Line& l : scene_lines(p[kReverse])) {
                if (p[kAlgorithm] == Algorithm::Dda)
                    line_dda(out.canvas, l.a, l.b, kWhite);
                else
                    line_bresenham(out.canvas, l.a, l.b, kWhite);
            }
            break;
        case Scene::Mesh:
        case Scene::Shading: {
            const bool shading = p[kScene] == Scene::Shading;
            const std::vector<WindowVertex> vs =
                shading ? shading_triangles() : mesh_triangles(p[kWinding]);
            const bool perspective = p[kInterpolation] == Interpolation::Perspective;
            const auto fill =
                p[kAlgorithm] == Algorithm::Scanline ? &fill_triangle_scanline : &fill_triangle;
            for (size_t i = 0; i + 2 < vs.size(); i += 3) {
                fill(out.canvas, &vs[i], !shading || perspective, shading && p[kDepthTest]);
                ++out.triangles;
            }
            break;
        }
        case Scene::Clipping: {
            const std::vector<ClipVertex> tri = clipping_triangle(p[kBehind]);
            out.triangles = draw_clip_triangle(out.canvas, tri.data(), true, false);
            break;
        }
    }
    return out;
}

}  // namespace rasterizer
