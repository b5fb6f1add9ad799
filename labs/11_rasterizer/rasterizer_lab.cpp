// Lab 11 `rasterizer`: the pipeline by hand.
//
// Teaches: what GL does between the vertex shader and the fragment shader,
// written on the CPU and compared pixel by pixel with GL's own rendering of
// the same scene: lines by DDA and Bresenham, triangles by edge functions
// with the pixel-centre and top-left rules, barycentric interpolation
// (affine and perspective-correct) with a depth buffer, and clipping against
// the near plane, the perspective divide and the viewport mapping.
// Lecture: rasterization (DDA, Bresenham, scanline), parameter interpolation
// with barycentric coordinates, clip space, the perspective divide and the
// viewport-to-window mapping.
// GL: glBindVertexArray and glDrawArrays with GL_LINES and GL_TRIANGLES,
// glBlendFunc(GL_ONE, GL_ONE) to count fragments, glDepthFunc(GL_LESS),
// smooth and noperspective outputs; the framework's texture takes the CPU
// image (GL_NEAREST magnification).
// Student parts (marked TODO): line_dda(), line_bresenham(), covers() (with
// top_left()), barycentric(), interpolate() and depth_test() in raster.cpp,
// clip_near() and to_window() in clip.cpp, fill_triangle_scanline() in
// scanline.cpp.
#include <cstddef>
#include <vector>

#include "compare.hpp"
#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "raster.hpp"
#include "scenes.hpp"
#include "unit_calls.hpp"
// A_POSITION, A_COLOR, OUTPUT_*, VIEW_*: shared with the shaders.
#include "shared.glsl"

namespace rasterizer {

namespace {

constexpr const char* kOutputUniform = "u_output";
constexpr const char* kViewUniform = "u_view";
constexpr const char* kCpuUniform = "u_cpu";
constexpr const char* kGlUniform = "u_gl";

// show.frag's u_view for view=gl and view=difference.
int view_gl_or_difference(const fw::ParamValues& p) {
    return p[kView] == View::Gl ? VIEW_GL : VIEW_DIFFERENCE;
}

}  // namespace

class RasterizerLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        fw::LabInfo i;
        i.title = "The pipeline by hand";
        i.aspect = 1.0;  // a square scene: letterboxed in a frame of another shape
        i.params = params();
        // What the unit checks call (unit_calls.hpp).
        i.functions = {fw::unit_function("line_dda", &line_dda_pixels),
                       fw::unit_function("line_bresenham", &line_bresenham_pixels),
                       fw::unit_function("top_left", &top_left_both),
                       fw::unit_function("covers", &covers_centres),
                       fw::unit_function("fill_triangle_scanline", &scanline_centres),
                       fw::unit_function("barycentric", &barycentric),
                       fw::unit_function("interpolate", &interpolate_at),
                       fw::unit_function("depth_test", &depth_test_at),
                       fw::unit_function("clip_near", &clip_near_at),
                       fw::unit_function("to_window", &to_window_at)};
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        scene_program_ = &programs.load({"scene.vert", "scene.frag"});
        show_program_ = &programs.load({"show.vert", "show.frag"});
        gl_fb_ = fw::Framebuffer({kGrid, kGrid, "GL's image"});
        count_fb_ = fw::Framebuffer({kGrid, kGrid, "fragment counts"});
        fw::Texture2DDesc desc;
        desc.width = kGrid;
        desc.height = kGrid;
        desc.min_filter = GL_NEAREST;
        desc.mag_filter = GL_NEAREST;
        desc.label = "CPU image";
        cpu_tex_ = fw::Texture2D(desc);
        show_vao_ = fw::VertexArray::blank("viewport triangle");
    }

    void draw(const fw::ParamValues& p, const fw::Frame&) override {
        GLint frame = 0, viewport[4] = {0, 0, 0, 0};
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &frame);
        glGetIntegerv(GL_VIEWPORT, viewport);

        cpu_ = cpu_scene(p);
        cpu_tex_.update(canvas_image(cpu_.canvas).pixels.data());
        draw_gl(p);

        glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(frame));
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        show_program_->use();
        cpu_tex_.bind(0);
        gl_fb_.color_texture().bind(1);
        show_program_->set(kCpuUniform, 0);
        show_program_->set(kGlUniform, 1);
        glBindVertexArray(show_vao_.id());
        const int x = viewport[0], y = viewport[1], w = viewport[2], h = viewport[3];
        if (p[kView] == View::Split) {
            show(VIEW_CPU, x, y + h / 4, w / 2, h / 2);
            show(VIEW_GL, x + w / 2, y + h / 4, w / 2, h / 2);
        } else {
            const int view = p[kView] == View::Cpu ? VIEW_CPU : view_gl_or_difference(p);
            show(view, x, y, w, h);
        }
        glBindVertexArray(0);
        glViewport(x, y, w, h);
    }

    // README.md, Stats: the CPU's and GL's fragment counts and how the two
    // images differ.
    nlohmann::json stats(const fw::ParamValues& p, const fw::Frame&) const override {
        const std::vector<Line> lines = scene_lines(p[kReverse]);
        return compare_stats(cpu_, gl_image_, gl_depth_, count_image_,
                             p[kScene] == Scene::Lines ? &lines : nullptr);
    }

private:
    // The scene through GL into gl_fb_, then once more with additive
    // blending into count_fb_, which then holds each pixel's fragment count.
    void draw_gl(const fw::ParamValues& p) {
        const GlScene scene = gl_scene(p);
        const fw::Buffer vbo = fw::Buffer::from(scene.vertices, GL_ARRAY_BUFFER, "scene");
        const fw::VertexArray vao = fw::VertexArray::blank("scene");
        glBindVertexArray(vao.id());
        glBindBuffer(GL_ARRAY_BUFFER, vbo.id());
        glVertexAttribPointer(A_POSITION, 4, GL_FLOAT, GL_FALSE, sizeof(ClipVertex),
                              reinterpret_cast<const void*>(offsetof(ClipVertex, clip)));
        glEnableVertexAttribArray(A_POSITION);
        glVertexAttribPointer(A_COLOR, 3, GL_FLOAT, GL_FALSE, sizeof(ClipVertex),
                              reinterpret_cast<const void*>(offsetof(ClipVertex, color)));
        glEnableVertexAttribArray(A_COLOR);
        const auto count = static_cast<GLsizei>(scene.vertices.size());
        scene_program_->use();
        glLineWidth(1.0f);

        gl_fb_.bind();
        glClearColor(0, 0, 0, 1);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        const bool depth = p[kScene] == Scene::Shading && p[kDepthTest];
        if (depth)
            glEnable(GL_DEPTH_TEST);
        else
            glDisable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        const bool affine =
            p[kScene] == Scene::Shading && p[kInterpolation] == Interpolation::Affine;
        scene_program_->set(kOutputUniform, affine ? OUTPUT_AFFINE : OUTPUT_SMOOTH);
        glDrawArrays(scene.mode, 0, count);
        gl_image_ = gl_fb_.read_color();
        gl_depth_ = gl_fb_.read_depth();

        count_fb_.bind();
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glDisable(GL_DEPTH_TEST);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
        scene_program_->set(kOutputUniform, OUTPUT_COUNT);
        glDrawArrays(scene.mode, 0, count);
        glDisable(GL_BLEND);
        count_image_ = count_fb_.read_color();
        glBindVertexArray(0);
    }

    void show(int view, int x, int y, int w, int h) {
        glViewport(x, y, w, h);
        show_program_->set(kViewUniform, view);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    fw::Program* scene_program_ = nullptr;
    fw::Program* show_program_ = nullptr;
    fw::Framebuffer gl_fb_, count_fb_;
    fw::Texture2D cpu_tex_;
    fw::VertexArray show_vao_;
    CpuScene cpu_;
    fw::Image gl_image_, count_image_;
    fw::DepthImage gl_depth_;
};

FW_LAB(RasterizerLab)

}  // namespace rasterizer
