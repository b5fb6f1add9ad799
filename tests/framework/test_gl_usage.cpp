// framework/trace/usage: each rule on a real context, with and without the
// mistake it names (a barrier, an enable, a complete texture, a second
// buffer, a unit number, a bounds check); the checker's own queries leave
// no GL error behind. Runs once per backend.
#include <glad/gl.h>

#include <string>
#include <vector>

#include "framework/gl.hpp"
#include "framework/trace/calls.hpp"
#include "framework/trace/usage.hpp"
#include "tests/support/test_support.hpp"

namespace {

using fw::gl_usage::Finding;

struct Point {
    glm::vec4 p;
};

// The checker observes this thread's calls for the scope, as in the grading child.
struct Observed {
    fw::gl_usage::Checker checker;
    fw::gl_calls::Observer* saved = fw::gl_calls::observe(&checker);
    Observed() { checker.begin_render(); }
    ~Observed() { fw::gl_calls::observe(saved); }
    std::vector<Finding> findings() {
        std::vector<Finding> out = checker.end_render();
        checker.begin_render();
        return out;
    }
};

fw::Program program(const std::vector<std::pair<fw::Stage, std::string>>& stages,
                    std::vector<std::string> feedback = {}) {
    std::vector<fw::Shader> shaders;
    for (const auto& [stage, source] : stages)
        shaders.push_back(fw::Shader::from_source(stage, "#version 430 core\n" + source,
                                                  std::string("test.") + fw::stage_name(stage)));
    return fw::Program::from_shaders(std::move(shaders), "test program", std::move(feedback));
}

// The rules of `found`, one line each, for a failing check's message.
std::string rules(const std::vector<Finding>& found) {
    std::string out;
    for (const Finding& f : found)
        out +=
            f.rule + " at " + f.call + " (draw " + std::to_string(f.draw) + "): " + f.detail + "\n";
    return out.empty() ? "(none)" : out;
}

const Finding* find(const std::vector<Finding>& found, const std::string& rule) {
    for (const Finding& f : found)
        if (f.rule == rule) return &f;
    return nullptr;
}

// No error and no debug message left by the checker's queries.
void check_no_gl_error() {
    CHECK(glGetError() == GL_NO_ERROR);
    CHECK(fw::take_debug_messages().empty());
}

constexpr const char* kWriteParticles = R"(
layout(local_size_x = 4) in;
layout(std430, binding = 0) buffer Particles { vec4 p[]; };
uniform uint u_count;
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= u_count) return;
    p[i] = vec4(0.1 * float(i), 0.5, 0.0, 1.0);
}
)";

constexpr const char* kPointsVert = R"(
layout(location = 0) in vec4 a_position;
void main() { gl_Position = a_position; gl_PointSize = 1.0; }
)";
constexpr const char* kWhiteFrag = R"(
out vec4 color;
void main() { color = vec4(1.0); }
)";

// A full-screen quad as a triangle strip of 4 vertices from gl_VertexID,
// with `more` added to the vertex shader's main().
std::string quad_vertex(const std::string& more = "") {
    return "const vec2 k[4] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(-1, 1), vec2(1, 1));\n"
           "void main() { gl_Position = vec4(k[gl_VertexID], 0, 1); " +
           more + " }\n";
}

// The quad drawn with `p` into a cleared `fb`; its colour at pixel (x, 4).
fw::Rgba8 draw_quad(const fw::Framebuffer& fb, const fw::Program& p, int x) {
    const fw::VertexArray empty = fw::VertexArray::blank("empty");
    fb.bind();
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    p.use();
    glBindVertexArray(empty.id());
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    const fw::Rgba8 c = fb.read_color().at(x, 4);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return c;
}

// A storage buffer of 8 vec4 that a dispatch writes, drawn from as points.
struct Particles {
    fw::Buffer buffer;
    fw::VertexArray vertices;
    fw::Program writer, drawer;
    fw::Framebuffer fb{{8, 8, "usage test"}};
    Particles() {
        fw::BufferDesc desc;
        desc.target = GL_SHADER_STORAGE_BUFFER;
        desc.size = 8 * sizeof(glm::vec4);
        desc.usage = GL_DYNAMIC_COPY;
        desc.label = "particles";
        buffer = fw::Buffer(desc);
        vertices = fw::VertexArray(
            fw::VertexArrayDesc{.vertices = &buffer,
                                .layout = fw::VertexLayout::of<Point>().attr(0, &Point::p),
                                .label = "particles"});
        writer = program({{fw::Stage::Compute, kWriteParticles}});
        writer.set("u_count", 8u);
        drawer = program({{fw::Stage::Vertex, kPointsVert}, {fw::Stage::Fragment, kWhiteFrag}});
    }
    void dispatch() {
        writer.use();
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer.id());
        glDispatchCompute(2, 1, 1);
    }
    void draw() {
        fb.bind();
        drawer.use();
        glBindVertexArray(vertices.id());
        glDrawArrays(GL_POINTS, 0, 8);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
};

}  // namespace

TEST_CASE("gl usage: a draw from what a dispatch wrote needs the vertex attribute barrier") {
    fw::enable_debug_output();
    Observed o;
    Particles p;
    o.findings();

    p.dispatch();
    p.draw();
    std::vector<Finding> found = o.findings();
    const Finding* f = find(found, "memory-barrier");
    REQUIRE_MESSAGE(f, rules(found));
    CHECK(f->call == "glDrawArrays");
    CHECK(f->draw == 2);  // the dispatch is the first
    fw::test::check_mentions(
        f->detail,
        {"the buffer 'particles'", "which call 1 (glDispatchCompute) wrote",
         "vertex attributes (location 0)", "glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT)"});

    for (GLbitfield bits :
         {GLbitfield(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT), GLbitfield(GL_ALL_BARRIER_BITS)}) {
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        p.dispatch();
        glMemoryBarrier(bits);
        p.draw();
        found = o.findings();
        CHECK_MESSAGE(found.empty(), rules(found));
        // The next dispatch reads the storage block this one wrote.
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    // Another bit does not make the vertices visible.
    p.dispatch();
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    p.draw();
    found = o.findings();
    CHECK_MESSAGE(find(found, "memory-barrier"), rules(found));
    check_no_gl_error();
}

TEST_CASE("gl usage: each way of reading what a dispatch wrote needs its own bit") {
    fw::enable_debug_output();
    Observed o;
    Particles p;
    o.findings();

    SUBCASE("read back") {
        p.dispatch();
        (void)p.buffer.read();
        std::vector<Finding> found = o.findings();
        const Finding* f = find(found, "memory-barrier");
        REQUIRE_MESSAGE(f, rules(found));
        CHECK(f->call == "glGetBufferSubData");
        CHECK(f->detail.find("GL_BUFFER_UPDATE_BARRIER_BIT") != std::string::npos);
        glMemoryBarrier(GL_ALL_BARRIER_BITS);
        p.dispatch();
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        (void)p.buffer.read();
        found = o.findings();
        CHECK_MESSAGE(found.empty(), rules(found));
    }
    SUBCASE("storage in the next dispatch") {
        p.dispatch();
        p.dispatch();
        std::vector<Finding> found = o.findings();
        const Finding* f = find(found, "memory-barrier");
        REQUIRE_MESSAGE(f, rules(found));
        CHECK(f->draw == 2);
        CHECK(f->detail.find("GL_SHADER_STORAGE_BARRIER_BIT") != std::string::npos);
        glMemoryBarrier(GL_ALL_BARRIER_BITS);
        p.dispatch();
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        p.dispatch();
        found = o.findings();
        CHECK_MESSAGE(found.empty(), rules(found));
    }
    SUBCASE("uniforms") {
        fw::Program reader =
            program({{fw::Stage::Vertex,
                      "layout(std140, binding = 2) uniform Block { vec4 u_p[8]; };\n"
                      "void main() { gl_Position = u_p[gl_VertexID]; }\n"},
                     {fw::Stage::Fragment, kWhiteFrag}});
        fw::VertexArray empty = fw::VertexArray::blank("empty");
        for (bool barrier : {false, true}) {
            p.dispatch();
            if (barrier) glMemoryBarrier(GL_UNIFORM_BARRIER_BIT);
            p.fb.bind();
            reader.use();
            glBindBufferBase(GL_UNIFORM_BUFFER, 2, p.buffer.id());
            glBindVertexArray(empty.id());
            glDrawArrays(GL_POINTS, 0, 8);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            std::vector<Finding> found = o.findings();
            const Finding* f = find(found, "memory-barrier");
            CHECK_MESSAGE(bool(f) == !barrier, rules(found));
            if (f) CHECK(f->detail.find("GL_UNIFORM_BARRIER_BIT") != std::string::npos);
            glMemoryBarrier(GL_ALL_BARRIER_BITS);
        }
    }
    check_no_gl_error();
}

TEST_CASE("gl usage: a clip distance written must be enabled") {
    fw::enable_debug_output();
    Observed o;
    // The left half of a full-screen quad's points, x < 0, is cut by the plane.
    fw::Program clipped =
        program({{fw::Stage::Vertex, quad_vertex("gl_ClipDistance[0] = k[gl_VertexID].x;")},
                 {fw::Stage::Fragment, kWhiteFrag}});
    fw::Framebuffer fb({8, 8, "clip test"});
    o.findings();
    bool left_lit[2] = {};
    for (bool enabled : {false, true}) {
        if (enabled) glEnable(GL_CLIP_DISTANCE0);
        left_lit[enabled] = draw_quad(fb, clipped, 1).r > 128;
        glDisable(GL_CLIP_DISTANCE0);
        std::vector<Finding> found = o.findings();
        const Finding* f = find(found, "clip-distance");
        CHECK_MESSAGE(bool(f) == !enabled, rules(found));
        if (f) {
            CHECK(f->call == "glDrawArrays");
            fw::test::check_mentions(
                f->detail, {"the program 'test program'", "vertex shader", "gl_ClipDistance[0]",
                            "GL_CLIP_DISTANCE0", "a GPU ignores"});
        }
    }
    // Why the check exists: llvmpipe clips by the distance enabled or not.
    if (fw::test::context_info().gl_renderer.find("llvmpipe") != std::string::npos)
        CHECK_MESSAGE(!left_lit[0], "llvmpipe no longer clips by a distance that is not enabled");
    CHECK(!left_lit[1]);
    check_no_gl_error();
}

TEST_CASE("gl usage: the clip distances a source writes") {
    using fw::gl_usage::clip_distances_written;
    CHECK(clip_distances_written("gl_ClipDistance[0] = 1.0;").indices == std::vector<int>{0});
    CHECK(clip_distances_written("#define PLANE 2\n void main() { gl_ClipDistance[PLANE] = d; }")
              .indices == std::vector<int>{2});
    CHECK(clip_distances_written("const int k = 3; gl_ClipDistance[ k ] += 1.0;").indices ==
          std::vector<int>{3});
    // A redeclared size bounds an index that is not constant.
    const auto sized = clip_distances_written(
        "out float gl_ClipDistance[2];\n for (int i = 0; i < 2; ++i) gl_ClipDistance[i] = 0.0;");
    CHECK(sized.known);
    CHECK(sized.indices == std::vector<int>{0, 1});
    CHECK(
        clip_distances_written("out gl_PerVertex { vec4 gl_Position; float gl_ClipDistance[3]; };\n"
                               "gl_ClipDistance = float[3](0.0, 1.0, 2.0);")
            .indices == std::vector<int>{0, 1, 2});
    // Reads, comparisons and comments write nothing.
    CHECK(clip_distances_written("gl_out[0].gl_ClipDistance[1] = 0.0; gl_ClipDistance[0] = x;")
              .indices == std::vector<int>{0});
    CHECK(clip_distances_written("if (gl_ClipDistance[1] == 0.0) {}").indices.empty());
    CHECK(clip_distances_written("// gl_ClipDistance[0] = 1.0;\n/* gl_ClipDistance[1] = 0; */")
              .indices.empty());
    CHECK(!clip_distances_written("gl_ClipDistance[i] = 0.0;").known);
}

TEST_CASE("gl usage: a sampler reads a complete texture") {
    fw::enable_debug_output();
    Observed o;
    fw::Program sampling = program({{fw::Stage::Vertex, quad_vertex()},
                                    {fw::Stage::Fragment,
                                     "uniform sampler2D u_texture; out vec4 color;\n"
                                     "void main() { color = texture(u_texture, vec2(0.5)); }\n"}});
    sampling.set("u_texture", 3);
    fw::Framebuffer fb({8, 8, "texture test"});
    const std::vector<std::uint8_t> white(16 * 16 * 4, 255);
    // Draws with the texture `texture` on unit 3: the finding, and the colour drawn.
    auto draw = [&](GLuint texture, const Finding** f, std::vector<Finding>& found) {
        glActiveTexture(GL_TEXTURE3);
        glBindTexture(GL_TEXTURE_2D, texture);
        glActiveTexture(GL_TEXTURE0);
        const fw::Rgba8 c = draw_quad(fb, sampling, 4);
        found = o.findings();
        *f = find(found, "incomplete-texture");
        return c;
    };
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, white.data());
    o.findings();
    std::vector<Finding> found;
    const Finding* f = nullptr;

    // The default min filter reads mipmaps, and there are none.
    fw::Rgba8 c = draw(tex, &f, found);
    REQUIRE_MESSAGE(f, rules(found));
    fw::test::check_mentions(f->detail,
                             {"the texture on unit 3", "u_texture", "GL_NEAREST_MIPMAP_LINEAR",
                              "level 1 has no image", "reads (0, 0, 0, 1)"});
    // Mesa reads GL's (0, 0, 0, 1) as a GPU does: the image shows it too.
    CHECK(c.r == 0);
    CHECK(c.a == 255);

    glBindTexture(GL_TEXTURE_2D, tex);
    glGenerateMipmap(GL_TEXTURE_2D);
    c = draw(tex, &f, found);
    CHECK_MESSAGE(!f, rules(found));
    CHECK(c.r == 255);

    // A level of the wrong size breaks the chain again.
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 2, GL_RGBA8, 3, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, white.data());
    c = draw(tex, &f, found);
    REQUIRE_MESSAGE(f, rules(found));
    CHECK(f->detail.find("level 2 is 3x3, not the 4x4") != std::string::npos);

    // A sampler object's filter is the one that counts.
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    GLuint sampler = 0;
    glGenSamplers(1, &sampler);
    glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glBindSampler(3, sampler);
    c = draw(tex, &f, found);
    REQUIRE_MESSAGE(f, rules(found));
    CHECK(f->detail.find("the sampler object's") != std::string::npos);
    glBindSampler(3, 0);
    c = draw(tex, &f, found);
    CHECK_MESSAGE(!f, rules(found));
    glDeleteSamplers(1, &sampler);

    // None bound.
    c = draw(0, &f, found);
    REQUIRE_MESSAGE(f, rules(found));
    CHECK(f->detail.find("no texture is bound to GL_TEXTURE_2D") != std::string::npos);

    // Immutable storage of one level is complete: GL clamps the levels a
    // mipmap filter reads to those it has (GL 4.3 section 8.14.3).
    fw::Texture2D one({16, 16, GL_RGBA8, white.data(), GL_RGBA, GL_UNSIGNED_BYTE, GL_LINEAR,
                       GL_LINEAR, GL_CLAMP_TO_EDGE, 1, "one level"});
    glBindTexture(GL_TEXTURE_2D, one.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    c = draw(one.id(), &f, found);
    CHECK_MESSAGE(!f, rules(found));
    CHECK(c.r == 255);
    glDeleteTextures(1, &tex);
    check_no_gl_error();
}

TEST_CASE("gl usage: a buffer is not captured and read by one draw") {
    fw::enable_debug_output();
    Observed o;
    fw::Program step = program({{fw::Stage::Vertex,
                                 "layout(location = 0) in vec4 a_p;\n"
                                 "out vec4 v_p;\n"
                                 "void main() { v_p = a_p + vec4(1.0); }\n"}},
                               {"v_p"});
    std::vector<glm::vec4> start(4, glm::vec4(0.0f));
    fw::Buffer a = fw::Buffer::from(start, GL_ARRAY_BUFFER, "a");
    fw::Buffer b = fw::Buffer::from(start, GL_ARRAY_BUFFER, "b");
    fw::VertexArray from_a(fw::VertexArrayDesc{
        .vertices = &a, .layout = fw::VertexLayout::of<Point>().attr(0, &Point::p), .label = "a"});
    fw::Framebuffer fb({4, 4, "capture test"});
    o.findings();
    for (const fw::Buffer* into : {&a, &b}) {
        fb.bind();
        step.use();
        glBindVertexArray(from_a.id());
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, into->id());
        glEnable(GL_RASTERIZER_DISCARD);
        glBeginTransformFeedback(GL_POINTS);
        glDrawArrays(GL_POINTS, 0, 4);
        glEndTransformFeedback();
        glDisable(GL_RASTERIZER_DISCARD);
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        std::vector<Finding> found = o.findings();
        const Finding* f = find(found, "capture-and-source");
        CHECK_MESSAGE(bool(f) == (into == &a), rules(found));
        if (f)
            fw::test::check_mentions(
                f->detail, {"the buffer 'a'", "binding 0", "vertex attributes (location 0)"});
    }
    check_no_gl_error();
}

TEST_CASE("gl usage: a sampler takes a unit's number, not GL_TEXTURE0") {
    fw::enable_debug_output();
    Observed o;
    fw::Program sampling =
        program({{fw::Stage::Vertex, "void main() { gl_Position = vec4(0.0); }\n"},
                 {fw::Stage::Fragment,
                  "uniform sampler2D u_texture; out vec4 color;\n"
                  "void main() { color = texture(u_texture, vec2(0.5)); }\n"}});
    o.findings();
    sampling.set("u_texture", 2);
    std::vector<Finding> found = o.findings();
    CHECK_MESSAGE(found.empty(), rules(found));
    check_no_gl_error();

    // What Mesa does with it: GL_INVALID_VALUE, which check_gl reports.
    sampling.set("u_texture", static_cast<int>(GL_TEXTURE0));
    const std::string error = fw::test::thrown<fw::Error>([] { fw::check_gl("the set"); });
    CHECK(error.find("GL_INVALID_VALUE") != std::string::npos);
    found = o.findings();
    const Finding* f = find(found, "sampler-unit");
    REQUIRE_MESSAGE(f, rules(found));
    CHECK(f->call == "glProgramUniform1i");
    fw::test::check_mentions(f->detail, {"the sampler u_texture", "33984", "GL_TEXTURE0",
                                         "unit's number, 0", "GL_INVALID_VALUE"});
    GLint unit = -1;
    glGetUniformiv(sampling.id(), glGetUniformLocation(sampling.id(), "u_texture"), &unit);
    CHECK(unit == 2);  // left as it was

    sampling.use();
    const GLint bad[1] = {-1};
    glUniform1iv(glGetUniformLocation(sampling.id(), "u_texture"), 1, bad);
    while (glGetError() != GL_NO_ERROR) {
    }
    fw::take_debug_messages();
    found = o.findings();
    CHECK_MESSAGE(find(found, "sampler-unit"), rules(found));
    glUseProgram(0);
}

TEST_CASE("gl usage: a dispatch writes nothing into the guard after its elements") {
    fw::enable_debug_output();
    Observed o;
    // Invocations past u_count write when the bounds check is left out.
    const std::string unchecked =
        std::string(kWriteParticles)
            .replace(std::string(kWriteParticles).find("if (i >= u_count) return;"), 25, "");
    for (bool checked : {true, false}) {
        Particles p;
        if (checked)
            p.writer.set("u_count", 3u);
        else
            p.writer = program({{fw::Stage::Compute, unchecked}});
        const std::vector<glm::vec4> sentinel(5, glm::vec4(-7.0f));
        p.buffer.update(3 * sizeof(glm::vec4), sentinel.data(), 5 * sizeof(glm::vec4));
        fw::gl_usage::guard(p.buffer.id(), 3 * sizeof(glm::vec4), 5 * sizeof(glm::vec4),
                            sizeof(glm::vec4), "the 3 particles");
        o.findings();
        p.dispatch();  // one group of 4: the fourth invocation is past the count
        glMemoryBarrier(GL_ALL_BARRIER_BITS);
        std::vector<Finding> found = o.findings();
        const Finding* f = find(found, "write-past-count");
        CHECK_MESSAGE(bool(f) == !checked, rules(found));
        if (f) {
            CHECK(f->call == "glDispatchCompute");
            CHECK(f->draw == 1);
            fw::test::check_mentions(f->detail, {"the 3 particles",
                                                 "element 3 of the buffer "
                                                 "'particles'",
                                                 "must do nothing"});
        }
        // The guard is the lab's: nothing else changed it.
        const std::vector<glm::vec4> after = p.buffer.read_as<glm::vec4>();
        CHECK((after[3] == glm::vec4(-7.0f)) == checked);
    }
    check_no_gl_error();
}
