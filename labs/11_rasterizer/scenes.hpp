// Lab 11's scenes as the parameters choose them (labs/11_rasterizer/README.md,
// The scenes): the choices, the parameters, each scene's vertices for GL and
// the CPU rasterizer's picture of it.
#pragma once

#include <glad/gl.h>

#include <glm/glm.hpp>
#include <vector>

#include "framework/params.hpp"
#include "raster.hpp"

namespace rasterizer {

// Both images are kGrid x kGrid pixels, shown magnified.
constexpr int kGrid = 32;

enum class Scene { Lines, Mesh, Shading, Clipping };
constexpr fw::Choice<Scene> kScenes[] = {{Scene::Lines, "lines"},
                                         {Scene::Mesh, "mesh"},
                                         {Scene::Shading, "shading"},
                                         {Scene::Clipping, "clipping"}};
enum class View { Split, Cpu, Gl, Difference };
constexpr fw::Choice<View> kViews[] = {
    {View::Split, "split"}, {View::Cpu, "cpu"}, {View::Gl, "gl"}, {View::Difference, "difference"}};
// dda and bresenham draw the lines (and fill the triangles by edge
// functions); scanline fills the triangles span by span (and draws the lines
// by Bresenham).
enum class Algorithm { Dda, Bresenham, Scanline };
constexpr fw::Choice<Algorithm> kAlgorithms[] = {{Algorithm::Dda, "dda"},
                                                 {Algorithm::Bresenham, "bresenham"},
                                                 {Algorithm::Scanline, "scanline"}};
enum class Winding { Ccw, Cw };
constexpr fw::Choice<Winding> kWindings[] = {{Winding::Ccw, "ccw"}, {Winding::Cw, "cw"}};
enum class Interpolation { Perspective, Affine };
constexpr fw::Choice<Interpolation> kInterpolations[] = {
    {Interpolation::Perspective, "perspective"}, {Interpolation::Affine, "affine"}};
enum class Behind { One, Two };
constexpr fw::Choice<Behind> kBehinds[] = {{Behind::One, "one"}, {Behind::Two, "two"}};

constexpr fw::ParamId<Scene> kScene{"scene"};
constexpr fw::ParamId<View> kView{"view"};
constexpr fw::ParamId<Algorithm> kAlgorithm{"algorithm"};
constexpr fw::ParamId<bool> kReverse{"reverse"};
constexpr fw::ParamId<Winding> kWinding{"winding"};
constexpr fw::ParamId<Interpolation> kInterpolation{"interpolation"};
constexpr fw::ParamId<bool> kDepthTest{"depth_test"};
constexpr fw::ParamId<Behind> kBehind{"behind"};
std::vector<fw::Param> params();

// scene=lines: the sheet's 8 segments, pixel to pixel, in disjoint boxes.
struct Line {
    glm::ivec2 a, b;
};
std::vector<Line> scene_lines(bool reverse);

// What GL draws: GL_LINES or GL_TRIANGLES of clip-space vertices.
struct GlScene {
    GLenum mode;
    std::vector<ClipVertex> vertices;
};
GlScene gl_scene(const fw::ParamValues& p);

// The CPU rasterizer's picture of the scene, and how many triangles it filled.
struct CpuScene {
    Canvas canvas{kGrid, kGrid};
    int triangles = 0;
};
CpuScene cpu_scene(const fw::ParamValues& p);

}  // namespace rasterizer
