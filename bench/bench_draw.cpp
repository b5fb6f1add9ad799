// bench_draw: what the GL wrapper costs per draw. The same frames (bind a
// framebuffer, clear, D draws of a small quad, glFinish) are drawn through
// fw::Program/VertexArray and with raw GL on the same objects, in alternating
// blocks of one run. Goal: wrapper/raw <= 1.02. Then what the loader's hooks
// cost with no observer (every GL call passes them: framework/trace/calls.hpp):
// the raw frames through the hooks against the same frames calling the
// driver's functions directly. Goal: hooks/direct <= 1.02. Prints figures;
// not a test.
//
//   bench_draw [backend] [draws per frame] [frames per block]
//     backend: auto, egl or osmesa (default $LAB_BACKEND, else auto)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "framework/context.hpp"
#include "framework/error.hpp"
#include "framework/gl.hpp"

namespace {

constexpr GLuint kPosition = 0;  // layout(location = 0) in the vertex shader
constexpr const char* kOffset = "u_offset";
constexpr const char* kColor = "u_color";
constexpr int kRounds = 10;  // each round: one block of wrapper frames, one of raw frames

const char* kVertexSource = R"(#version 430 core
layout(location = 0) in vec2 a_position;
uniform vec2 u_offset;
void main() { gl_Position = vec4(a_position + u_offset, 0.0, 1.0); }
)";
const char* kFragmentSource = R"(#version 430 core
uniform vec3 u_color;
out vec4 frag_color;
void main() { frag_color = vec4(u_color, 1.0); }
)";

struct Vertex {
    glm::vec2 position;
};

// Everything both variants draw with: the raw variant uses the id()s.
struct Scene {
    int draws = 0;
    fw::Framebuffer target;
    fw::Program program;
    fw::Buffer vertices, indices;
    fw::VertexArray vao;
    std::vector<glm::vec2> offsets;  // one per draw, the same in both variants
    std::vector<glm::vec3> colors;
};

Scene make_scene(int draws) {
    Scene s;
    s.draws = draws;
    s.target = fw::Framebuffer({256, 256, "bench target"});
    std::vector<fw::Shader> stages;
    stages.push_back(fw::Shader::from_source(fw::Stage::Vertex, kVertexSource, "bench.vert"));
    stages.push_back(fw::Shader::from_source(fw::Stage::Fragment, kFragmentSource, "bench.frag"));
    s.program = fw::Program::from_shaders(std::move(stages), "bench_draw");
    // A quad 4 pixels wide as two triangles; the indexed draw reads the same six vertices.
    const float q = 4.0f / 256.0f;
    s.vertices = fw::Buffer::from(
        std::vector<Vertex>{{{0, 0}}, {{q, 0}}, {{q, q}}, {{0, 0}}, {{q, q}}, {{0, q}}},
        GL_ARRAY_BUFFER, "quad vertices");
    s.indices = fw::Buffer::from(std::vector<GLuint>{0, 1, 2, 3, 4, 5}, GL_ELEMENT_ARRAY_BUFFER,
                                 "quad indices");
    s.vao = fw::VertexArray({&s.vertices,
                             fw::VertexLayout::of<Vertex>().attr(kPosition, &Vertex::position),
                             &s.indices, GL_UNSIGNED_INT, "quad"});
    for (int i = 0; i < draws; ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(draws);
        s.offsets.emplace_back(1.8f * t - 0.9f,
                               0.9f - 1.8f * static_cast<float>((i * 37) % 101) / 101.0f);
        s.colors.emplace_back(t, 1.0f - t, 0.5f);
    }
    return s;
}

enum class Mode { Uniforms, DrawOnly, Indexed };

// The wrapper, as a lab writes it.
void wrapper_frame(const Scene& s, Mode mode) {
    s.target.bind();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    s.program.use();
    for (int i = 0; i < s.draws; ++i) {
        if (mode == Mode::Uniforms) {
            s.program.set(kOffset, s.offsets[i]);
            s.program.set(kColor, s.colors[i]);
        }
        if (mode == Mode::Indexed)
            s.vao.draw_indexed(GL_TRIANGLES, 6);
        else
            s.vao.draw(GL_TRIANGLES, 6);
    }
    glFinish();
}

// The GL functions a raw frame calls: through the loader's hooks (what the
// glXxx names are) or the driver's own (glad_glXxx), read when the frame
// starts, as a call through either name reads its pointer.
struct RawGl {
    PFNGLBINDFRAMEBUFFERPROC bind_framebuffer;
    PFNGLVIEWPORTPROC viewport;
    PFNGLCLEARPROC clear;
    PFNGLUSEPROGRAMPROC use_program;
    PFNGLBINDVERTEXARRAYPROC bind_vertex_array;
    PFNGLPROGRAMUNIFORM2FPROC uniform2f;
    PFNGLPROGRAMUNIFORM3FPROC uniform3f;
    PFNGLDRAWELEMENTSPROC draw_elements;
    PFNGLDRAWARRAYSPROC draw_arrays;
    PFNGLFINISHPROC finish;
};

RawGl hooked_gl() {
    return {glBindFramebuffer,  glViewport,         glClear,        glUseProgram, glBindVertexArray,
            glProgramUniform2f, glProgramUniform3f, glDrawElements, glDrawArrays, glFinish};
}

RawGl direct_gl() {
    return {glad_glBindFramebuffer,
            glad_glViewport,
            glad_glClear,
            glad_glUseProgram,
            glad_glBindVertexArray,
            glad_glProgramUniform2f,
            glad_glProgramUniform3f,
            glad_glDrawElements,
            glad_glDrawArrays,
            glad_glFinish};
}

// Raw GL, as a careful hand-written loop does it: locations looked up once,
// the vertex array bound once.
void raw_frame(const RawGl& gl, const Scene& s, Mode mode, GLint offset_loc, GLint color_loc) {
    const GLuint prog = s.program.id();
    gl.bind_framebuffer(GL_FRAMEBUFFER, s.target.id());
    gl.viewport(0, 0, s.target.width(), s.target.height());
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.use_program(prog);
    gl.bind_vertex_array(s.vao.id());
    for (int i = 0; i < s.draws; ++i) {
        if (mode == Mode::Uniforms) {
            gl.uniform2f(prog, offset_loc, s.offsets[i].x, s.offsets[i].y);
            gl.uniform3f(prog, color_loc, s.colors[i].r, s.colors[i].g, s.colors[i].b);
        }
        if (mode == Mode::Indexed)
            gl.draw_elements(GL_TRIANGLES, 6, GL_UNSIGNED_INT, nullptr);
        else
            gl.draw_arrays(GL_TRIANGLES, 0, 6);
    }
    gl.finish();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

// Milliseconds of each frame. Rounds alternate which variant goes first, so
// clock or thermal drift within the run falls on both alike.
struct Samples {
    std::vector<double> wrapper, raw, round_ratios;
};

Samples measure(const std::function<void()>& wrapper, const std::function<void()>& raw,
                int frames) {
    auto block = [frames](const std::function<void()>& frame, std::vector<double>& out) {
        std::vector<double> ms;
        for (int f = 0; f < frames; ++f) {
            const auto start = std::chrono::steady_clock::now();
            frame();
            ms.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
        }
        out.insert(out.end(), ms.begin(), ms.end());
        return median(ms);
    };
    Samples s, warmup;
    block(wrapper, warmup.wrapper);
    block(raw, warmup.raw);
    for (int r = 0; r < kRounds; ++r) {
        double w = 0, g = 0;
        if (r % 2 == 0) {
            w = block(wrapper, s.wrapper);
            g = block(raw, s.raw);
        } else {
            g = block(raw, s.raw);
            w = block(wrapper, s.wrapper);
        }
        s.round_ratios.push_back(w / g);
    }
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const fw::Backend backend = argc > 1 ? fw::parse_backend(argv[1]) : fw::backend_from_env();
        const int draws = argc > 2 ? std::atoi(argv[2]) : 2000;
        const int frames = argc > 3 ? std::atoi(argv[3]) : 10;
        if (draws < 1 || frames < 1) {
            std::fprintf(stderr, "bench_draw: draws and frames must be positive integers\n");
            return 2;
        }
        auto context = fw::create_offscreen_context(backend);
        std::printf("backend %s, %s\n", context->info().backend.c_str(),
                    context->info().gl_renderer.c_str());
        std::printf("%d draws per frame, %d rounds x %d frames per variant, medians\n\n", draws,
                    kRounds, frames);

        const Scene scene = make_scene(draws);
        const GLint offset_loc = glGetUniformLocation(scene.program.id(), kOffset);
        const GLint color_loc = glGetUniformLocation(scene.program.id(), kColor);

        const struct {
            const char* name;
            Mode mode;
        } scenarios[] = {{"2 uniforms+draw", Mode::Uniforms},
                         {"draw only", Mode::DrawOnly},
                         {"indexed only", Mode::Indexed}};
        const RawGl hooked = hooked_gl(), direct = direct_gl();
        bool met = true;
        // One table: a (the measured variant) against b (its baseline).
        auto table = [&](const char* a_name, const char* b_name, const std::function<void(Mode)>& a,
                         const std::function<void(Mode)>& b) {
            std::printf("%-16s %10s %10s %12s %12s %7s  %s\n", "scenario",
                        (std::string(a_name) + " ms").c_str(),
                        (std::string(b_name) + " ms").c_str(),
                        (std::string(a_name) + " us/d").c_str(),
                        (std::string(b_name) + " us/d").c_str(), "ratio", "round ratios");
            for (const auto& sc : scenarios) {
                // Same work: both variants must leave the same pixels.
                a(sc.mode);
                const fw::Image expected = scene.target.read_color();
                b(sc.mode);
                if (scene.target.read_color().pixels != expected.pixels)
                    throw fw::Error(std::string("bench_draw: ") + a_name + " and " + b_name +
                                    " frames differ in " + sc.name);
                fw::check_gl(sc.name);

                const Samples s = measure([&] { a(sc.mode); }, [&] { b(sc.mode); }, frames);
                fw::check_gl(sc.name);
                const double w = median(s.wrapper), g = median(s.raw), ratio = w / g;
                const auto [lo, hi] =
                    std::minmax_element(s.round_ratios.begin(), s.round_ratios.end());
                std::printf("%-16s %10.3f %10.3f %12.3f %12.3f %7.3f  %.3f..%.3f\n", sc.name, w, g,
                            1000 * w / draws, 1000 * g / draws, ratio, *lo, *hi);
                met = met && ratio <= 1.02;
            }
        };
        table(
            "wrapper", "raw", [&](Mode m) { wrapper_frame(scene, m); },
            [&](Mode m) { raw_frame(hooked, scene, m, offset_loc, color_loc); });
        std::printf(
            "\nthe loader's hooks, no observer: raw GL through them against the driver's\n"
            "functions called directly\n");
        table(
            "hooks", "direct", [&](Mode m) { raw_frame(hooked, scene, m, offset_loc, color_loc); },
            [&](Mode m) { raw_frame(direct, scene, m, offset_loc, color_loc); });
        std::printf("\ngoal <= 1.02 (both tables): %s\n", met ? "met" : "NOT met");
        return 0;
    } catch (const fw::Error& e) {
        std::fprintf(stderr, "bench_draw: %s\n", e.what());
        return fw::exit_code_for(e);
    }
}
