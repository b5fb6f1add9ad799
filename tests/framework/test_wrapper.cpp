// The GL wrapper (framework/gl), piglit style: set up, draw, probe, with
// Expected/Observed printed for every probe. Runs once per backend.
#include <glad/gl.h>

#include <cstddef>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/gl.hpp"
#include "framework/gl/binding.hpp"
#include "framework/lab.hpp"
#include "tests/support/test_support.hpp"

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

namespace {

constexpr GLuint kPosition = 0, kColor = 1, kUv = 1, kCell = 2;
const glm::vec3 kBlack(0, 0, 0), kRed(1, 0, 0), kGreen(0, 1, 0), kBlue(0, 0, 1), kWhite(1, 1, 1);

struct ColorVertex {
    glm::vec3 position;
    glm::vec3 color;
};

fw::VertexLayout color_layout() {
    return fw::VertexLayout::of<ColorVertex>()
        .attr(kPosition, &ColorVertex::position)
        .attr(kColor, &ColorVertex::color);
}

// Two counter-clockwise triangles covering [x0, x1] x [y0, y1] at NDC depth z.
std::vector<ColorVertex> quad(float x0, float y0, float x1, float y1, float z, glm::vec3 c) {
    return {{{x0, y0, z}, c}, {{x1, y0, z}, c}, {{x1, y1, z}, c},
            {{x0, y0, z}, c}, {{x1, y1, z}, c}, {{x0, y1, z}, c}};
}

void clear_black() {
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

using fw::test::check_mentions;
using fw::test::thrown;

// Leaves no GL error or debug message behind for the next test.
void drain_gl_errors() {
    while (glGetError() != GL_NO_ERROR) {
    }
    fw::take_debug_messages();
}

std::string to_text(const std::vector<float>& v) {
    std::string out;
    for (float f : v) out += (out.empty() ? "" : " ") + std::to_string(f);
    return "[" + out + "]";
}

int count_pixels(const fw::Image& img, fw::Rgba8 colour) {
    int n = 0;
    for (const fw::Rgba8& p : img.pixels) n += p == colour ? 1 : 0;
    return n;
}

}  // namespace

TEST_CASE("buffer: update and read round trip, ranges checked") {
    const std::vector<float> data{1, 2, 3, 4, 5, 6, 7, 8};
    fw::Buffer buf = fw::Buffer::from(data, GL_ARRAY_BUFFER, "round trip");
    CHECK(buf.size() == 32);
    CHECK(fw::object_label(GL_BUFFER, buf.id()) == "round trip");

    const std::vector<float> patch{-1, -2};
    buf.update(2 * sizeof(float), patch.data(), 2 * sizeof(float));
    const std::vector<float> expected{1, 2, -1, -2, 5, 6, 7, 8};
    const std::vector<float> observed = buf.read_as<float>();
    CHECK_MESSAGE(observed == expected,
                  "expected " << to_text(expected) << " observed " << to_text(observed));

    std::vector<std::uint8_t> tail = buf.read(6 * sizeof(float));
    REQUIRE(tail.size() == 8);
    float seventh = 0;
    std::memcpy(&seventh, tail.data(), sizeof seventh);
    CHECK(seventh == 7.0f);

    check_mentions(thrown<fw::UsageError>([&] { buf.update(30, patch.data(), 8); }),
                   {"'round trip'", "update of bytes [30, 38)", "32 bytes"});
    check_mentions(thrown<fw::UsageError>([&] { buf.read(40, 4); }), {"read of bytes [40, 44)"});
    check_mentions(thrown<fw::UsageError>([] {
                       fw::BufferDesc desc;
                       desc.label = "empty";
                       fw::Buffer b(desc);
                   }),
                   {"BufferDesc.size must be greater than zero", "'empty'"});

    fw::Buffer moved = std::move(buf);
    CHECK(buf.id() == 0);
    CHECK(moved.id() != 0);
}

TEST_CASE("vertex array: vec3, vec2 and ivec2 attributes from one struct all arrive") {
    struct Vertex {
        glm::vec3 position;
        glm::vec2 uv;
        glm::ivec2 cell;
    };
    fw::VertexLayout layout = fw::VertexLayout::of<Vertex>()
                                  .attr(kPosition, &Vertex::position)
                                  .attr(kUv, &Vertex::uv)
                                  .attr(kCell, &Vertex::cell);
    REQUIRE(layout.attributes().size() == 3);
    CHECK(layout.stride() == sizeof(Vertex));
    CHECK(layout.attributes()[1].offset == 12);
    CHECK(layout.attributes()[1].components == 2);
    CHECK(layout.attributes()[2].offset == 20);
    CHECK(layout.attributes()[2].type == GL_INT);
    CHECK(layout.attributes()[2].integer);

    // Four vertical strips; strip k has uv (0.2 (k+1), 1 - 0.2 (k+1)) and
    // cell (k+1, 2k+3), so blue = ((k+1) * 16 + 2k+3) / 255.
    std::vector<Vertex> vertices;
    for (int k = 0; k < 4; ++k) {
        float x0 = -1.0f + 0.5f * k, x1 = x0 + 0.5f, u = 0.2f * (k + 1);
        glm::ivec2 cell(k + 1, 2 * k + 3);
        for (glm::vec2 p : {glm::vec2(x0, -1), glm::vec2(x1, -1), glm::vec2(x1, 1),
                            glm::vec2(x0, -1), glm::vec2(x1, 1), glm::vec2(x0, 1)})
            vertices.push_back({glm::vec3(p, 0.0f), glm::vec2(u, 1.0f - u), cell});
    }
    fw::Buffer vbo = fw::Buffer::from(vertices, GL_ARRAY_BUFFER, "strips");
    fw::VertexArray vao({&vbo, layout, nullptr, GL_UNSIGNED_INT, "strips"});
    CHECK(vao.vertex_count() == 24);
    fw::Program prog = fw::Program::from_files({"tests/attribs.vert", "tests/attribs.frag"});

    fw::Framebuffer fb({64, 16, "attributes"});
    fb.bind();
    clear_black();
    prog.use();
    vao.draw(GL_TRIANGLES, 24);
    fw::check_gl("attribute draw");
    fw::Image img = fb.read_color();
    bool pass = true;
    for (int k = 0; k < 4; ++k) {
        float u = 0.2f * (k + 1);
        glm::vec3 expected(u, 1.0f - u, ((k + 1) * 16 + 2 * k + 3) / 255.0f);
        pass = fw::test::probe_rgb(img, 8 + 16 * k, 8, expected) && pass;
    }
    CHECK(pass);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_CASE("vertex array: indexed and flat storage draw the same image") {
    // The lecture's indexed face set: 6 vertices, 4 triangles.
    const glm::vec3 yellow(1, 1, 0), cyan(0, 1, 1), magenta(1, 0, 1);
    const std::vector<ColorVertex> vertices = {
        {{-0.8f, -0.8f, 0}, kRed},  {{0.0f, -0.8f, 0}, kGreen}, {{-0.4f, 0.0f, 0}, kBlue},
        {{0.8f, -0.8f, 0}, yellow}, {{0.4f, 0.0f, 0}, cyan},    {{0.0f, 0.8f, 0}, magenta}};
    const std::vector<GLuint> indices = {0, 2, 1, 1, 3, 4, 1, 4, 2, 2, 4, 5};
    std::vector<ColorVertex> flat;
    for (GLuint i : indices) flat.push_back(vertices[i]);

    fw::Buffer indexed_vbo = fw::Buffer::from(vertices, GL_ARRAY_BUFFER, "indexed vertices");
    fw::Buffer ibo = fw::Buffer::from(indices, GL_ELEMENT_ARRAY_BUFFER, "indices");
    fw::Buffer flat_vbo = fw::Buffer::from(flat, GL_ARRAY_BUFFER, "flat vertices");
    fw::VertexArray indexed({&indexed_vbo, color_layout(), &ibo, GL_UNSIGNED_INT, "indexed"});
    fw::VertexArray expanded({&flat_vbo, color_layout(), nullptr, GL_UNSIGNED_INT, "flat"});
    CHECK(indexed.index_count() == 12);
    fw::Program prog = fw::Program::from_files({"tests/color.vert", "tests/color.frag"});
    prog.use();

    fw::Framebuffer fb_indexed({64, 64, "indexed"}), fb_flat({64, 64, "flat"});
    fb_indexed.bind();
    clear_black();
    indexed.draw_indexed(GL_TRIANGLES, 12);
    fb_flat.bind();
    clear_black();
    expanded.draw(GL_TRIANGLES, 12);
    fw::check_gl("indexed and flat draws");
    fw::Image a = fb_indexed.read_color(), b = fb_flat.read_color();

    int differing = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) differing += a.pixels[i] != b.pixels[i];
    int covered = static_cast<int>(a.pixels.size()) - count_pixels(a, {0, 0, 0, 255});
    MESSAGE("pixels covered " << covered << ", differing between indexed and flat " << differing);
    CHECK(covered > 500);
    CHECK(differing == 0);
    // Near the centroid of the top triangle (blue, cyan, magenta).
    CHECK(fw::test::probe_rgb(a, 32, 40, glm::vec3(1.0f / 3, 1.0f / 3, 1.0f), 0.06f));

    check_mentions(thrown<fw::UsageError>([&] { expanded.draw_indexed(GL_TRIANGLES, 3); }),
                   {"'flat'", "no index buffer"});
    check_mentions(thrown<fw::UsageError>([&] { expanded.draw(GL_TRIANGLES, 13); }),
                   {"[0, 13)", "holds 12"});
    check_mentions(thrown<fw::UsageError>([&] { indexed.draw_indexed(GL_TRIANGLES, 6, 9); }),
                   {"[9, 15)", "holds 12"});
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_CASE("vertex array: a blank one described by hand draws as one described by the wrapper") {
    const std::vector<ColorVertex> vertices = {
        {{-0.8f, -0.8f, 0}, kRed}, {{0.8f, -0.8f, 0}, kGreen}, {{0.0f, 0.8f, 0}, kBlue}};
    fw::Buffer vbo = fw::Buffer::from(vertices, GL_ARRAY_BUFFER, "triangle");
    fw::VertexArray wrapped({.vertices = &vbo, .layout = color_layout(), .label = "wrapped"});
    fw::VertexArray blank = fw::VertexArray::blank("by hand");
    CHECK(fw::object_label(GL_VERTEX_ARRAY, blank.id()) == "by hand");
    CHECK(blank.vertex_count() == 0);
    glBindVertexArray(blank.id());
    glBindBuffer(GL_ARRAY_BUFFER, vbo.id());
    glVertexAttribPointer(kPosition, 3, GL_FLOAT, GL_FALSE, sizeof(ColorVertex),
                          reinterpret_cast<const void*>(offsetof(ColorVertex, position)));
    glEnableVertexAttribArray(kPosition);
    glVertexAttribPointer(kColor, 3, GL_FLOAT, GL_FALSE, sizeof(ColorVertex),
                          reinterpret_cast<const void*>(offsetof(ColorVertex, color)));
    glEnableVertexAttribArray(kColor);
    glBindVertexArray(0);

    // The program takes its locations from an #include of shared.glsl.
    fw::Program prog = fw::Program::from_files({"tests/included.vert", "tests/color.frag"});
    prog.use();
    fw::Framebuffer fb_wrapped({64, 64, "wrapped"}), fb_blank({64, 64, "blank"});
    fb_wrapped.bind();
    clear_black();
    wrapped.draw(GL_TRIANGLES, 3);
    fb_blank.bind();
    clear_black();
    glBindVertexArray(blank.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    fw::check_gl("wrapped and hand-described draws");
    const fw::Image a = fb_wrapped.read_color(), b = fb_blank.read_color();
    const int covered = static_cast<int>(a.pixels.size()) - count_pixels(a, {0, 0, 0, 255});
    MESSAGE("pixels covered " << covered);
    CHECK(covered > 800);
    CHECK(a.pixels == b.pixels);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_CASE("vertex array: a draw never uses a binding the lab changed since the wrapper's last") {
    // Red on the left half, green on the right: which one a draw used shows.
    fw::Buffer left_vbo = fw::Buffer::from(quad(-1, -1, 0, 1, 0, kRed), GL_ARRAY_BUFFER, "left");
    fw::Buffer right_vbo = fw::Buffer::from(quad(0, -1, 1, 1, 0, kGreen), GL_ARRAY_BUFFER, "right");
    fw::VertexArray left({.vertices = &left_vbo, .layout = color_layout(), .label = "left"});
    fw::VertexArray right({.vertices = &right_vbo, .layout = color_layout(), .label = "right"});
    fw::Program prog = fw::Program::from_files({"tests/color.vert", "tests/color.frag"});
    prog.use();
    fw::Framebuffer fb({32, 32, "stale binding"});
    fb.bind();
    // Which halves a wrapper draw of `left` coloured, after `between` ran.
    auto draw_left_after = [&](const std::function<void()>& between) {
        clear_black();
        left.draw(GL_TRIANGLES, 6);  // the wrapper binds `left` and knows it
        clear_black();
        between();
        left.draw(GL_TRIANGLES, 6);
        fw::check_gl("draw after a raw call");
        const fw::Image img = fb.read_color();
        return std::pair{img.at(8, 16), img.at(24, 16)};
    };
    const fw::Rgba8 red{255, 0, 0, 255}, green{0, 255, 0, 255}, black{0, 0, 0, 255};
    const std::vector<std::pair<std::string, std::function<void()>>> cases = {
        {"nothing", [] {}},
        {"glBindVertexArray(right)", [&] { glBindVertexArray(right.id()); }},
        {"glBindVertexArray(0)", [] { glBindVertexArray(0); }},
        {"right.bind()", [&] { right.bind(); }},
        {"a scoped binding of right, restored",
         [&] { const fw::ScopedBinding b = fw::bind_vertex_array_scoped(right.id()); }},
        {"raw draws of right", [&] {
             glBindVertexArray(right.id());
             glDrawArrays(GL_TRIANGLES, 0, 6);
         }}};
    for (const auto& [name, between] : cases) {
        CAPTURE(name);
        const auto [l, r] = draw_left_after(between);
        CHECK(l == red);
        CHECK(r == (name == "raw draws of right" ? green : black));
    }
    // Any glDeleteVertexArrays forgets the binding, even of a name never bound
    // (after a deletion, a name may come back as a new vertex array).
    left.draw(GL_TRIANGLES, 6);
    CHECK(fw::detail::vertex_array_binding_known());
    GLuint never_bound = 0;
    glGenVertexArrays(1, &never_bound);
    glDeleteVertexArrays(1, &never_bound);
    CHECK_FALSE(fw::detail::vertex_array_binding_known());
    // A vertex array deleted and its name reused: the new one is bound anew.
    GLuint reused = 0;
    {
        fw::Buffer vbo = fw::Buffer::from(quad(0, -1, 1, 1, 0, kBlue), GL_ARRAY_BUFFER, "blue");
        fw::VertexArray blue({.vertices = &vbo, .layout = color_layout(), .label = "blue"});
        clear_black();
        blue.draw(GL_TRIANGLES, 6);
        reused = blue.id();
    }
    fw::Buffer vbo = fw::Buffer::from(quad(-1, -1, 0, 1, 0, kWhite), GL_ARRAY_BUFFER, "white");
    fw::VertexArray white({.vertices = &vbo, .layout = color_layout(), .label = "white"});
    MESSAGE("deleted name " << reused << ", new name " << white.id());
    clear_black();
    white.draw(GL_TRIANGLES, 6);
    const fw::Image img = fb.read_color();
    CHECK(img.at(8, 16) == fw::Rgba8{255, 255, 255, 255});
    CHECK(img.at(24, 16) == black);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_CASE("shader: an error in an #included file names that file and quotes its line") {
    fw::enable_debug_output();
    const auto compile = [] {
        fw::Program::from_files({"tests/color.vert", "tests/broken_include.frag"});
    };
    const std::string msg = thrown(compile);
    check_mentions(msg,
                   {"shaders/tests/broken_shared.glsl:3:", "fragment shader failed to compile",
                    "undeclared_grey",
                    "shaders/tests/broken_shared.glsl:3 | const vec3 kGrey = undeclared_grey;"});
    CHECK_NOTHROW(fw::check_gl("after a failed compile"));
}

TEST_CASE("shader: a compile error names the file, the stage, the line and quotes it") {
    fw::enable_debug_output();  // as `lab` runs: GL's debug messages collected
    const auto compile = [] { fw::Program::from_files({"tests/color.vert", "tests/broken.frag"}); };
    std::string msg = thrown(compile);
    check_mentions(msg, {"shaders/tests/broken.frag:9:", "fragment shader failed to compile",
                         "undeclared_colour", "  9 |     o_color = vec4(undeclared_colour, 1.0);"});

    // The failure is reported once, by the exception: GL's own copy of it
    // (KHR_debug) must not resurface as an error of the next draw.
    CHECK_NOTHROW(fw::check_gl("after a failed compile"));

    check_mentions(thrown([] { fw::Shader::from_file("tests/does_not_exist.frag"); }),
                   {"cannot read shader file", "tests/does_not_exist.frag", fw::shader_dir()});
    check_mentions(thrown<fw::UsageError>([] { fw::Shader::from_file("tests/color.glsl"); }),
                   {"tests/color.glsl", ".vert", ".frag", ".comp", "tessellation control"});
}

TEST_CASE(
    "shader: a text set in place of a file is compiled instead, its includes from that folder") {
    fw::enable_debug_output();
    // The file does not compile; the text that stands in for it does, with
    // shared.glsl of the file's folder (shaders/tests/).
    fw::set_shader_overrides({{"tests/broken.frag",
                               "#version 430 core\n#include \"shared.glsl\"\n"
                               "in vec3 v_color;\nout vec4 o_color;\n"
                               "void main() { o_color = vec4(v_color, "
                               "float(A_COLOR)); }\n"}});
    fw::Program stand_in = fw::Program::from_files({"tests/color.vert", "tests/broken.frag"});
    CHECK(stand_in.build_error() == nullptr);
    // Only the file named: another keeps its own text.
    check_mentions(thrown([] { fw::Shader::from_file("tests/broken_include.frag"); }),
                   {"shaders/tests/broken_shared.glsl:3:"});
    // An error in the text names the file it stands for.
    fw::set_shader_overrides({{"tests/broken.frag",
                               "#version 430 core\nout vec4 o_color;\n"
                               "void main() { o_color = nothing_here; }\n"}});
    check_mentions(thrown([] { fw::Shader::from_file("tests/broken.frag"); }),
                   {"shaders/tests/broken.frag:3:", "nothing_here"});
    // Ended: the file again.
    fw::set_shader_overrides({});
    check_mentions(thrown([] { fw::Shader::from_file("tests/broken.frag"); }),
                   {"shaders/tests/broken.frag:9:", "undeclared_colour"});
    CHECK_NOTHROW(fw::check_gl("after the failed compiles"));
}

TEST_CASE("program library: a program that does not build fails only where it is used") {
    fw::enable_debug_output();
    fw::ProgramLibrary programs("tests");
    fw::Program& good = programs.load({"color.vert", "color.frag"});
    fw::Program& broken = programs.load({"color.vert", "broken.frag"});
    CHECK(good.build_error() == nullptr);
    CHECK_NOTHROW(good.use());
    REQUIRE(broken.build_error() != nullptr);
    CHECK(broken.build_error()->file() == "shaders/tests/broken.frag");
    // Every use of the failed program throws the compiler's message again.
    for (const auto& use : std::vector<std::function<void()>>{
             [&] { broken.use(); }, [&] { (void)broken.id(); },
             [&] { broken.set("u_color", glm::vec3(1.0f)); },
             [&] { broken.set_if_active("u_color", glm::vec3(1.0f)); }})
        check_mentions(thrown<fw::ShaderError>(use),
                       {"shaders/tests/broken.frag:9:", "undeclared_colour"});
    const std::vector<const fw::ShaderError*> errors = programs.build_errors();
    REQUIRE(errors.size() == 1);
    CHECK(errors[0]->file() == "shaders/tests/broken.frag");
    // A reload that still fails keeps it failed, with the message again.
    const std::vector<std::string> reloaded = programs.reload_all();
    REQUIRE(reloaded.size() == 1);
    check_mentions(reloaded[0], {"shaders/tests/broken.frag:9:"});
    CHECK(programs.build_errors().size() == 1);
    CHECK_NOTHROW(fw::check_gl("after the failed builds"));
}

TEST_CASE("program: a link error names the files and gives the linker's log") {
    fw::enable_debug_output();
    const auto link = [] {
        fw::Program::from_files({"tests/unlinked.vert", "tests/unlinked.frag"});
    };
    std::string msg = thrown(link);
    check_mentions(msg,
                   {"failed to link", "tests/unlinked.vert", "tests/unlinked.frag", "displace"});
    CHECK_NOTHROW(fw::check_gl("after a failed link"));

    fw::Program ok = fw::Program::from_files({"tests/color.vert", "tests/color.frag"});
    CHECK(ok.label() == "tests/color.vert + color.frag");
    CHECK(fw::object_label(GL_PROGRAM, ok.id()) == ok.label());
    CHECK(ok.files() == std::vector<std::string>{"tests/color.vert", "tests/color.frag"});
}

TEST_CASE("framebuffer: window pixel (x, y) is Image at(x, y) and PNG row H-1-y") {
    const int w = 16, h = 8, x = 3, y = 5;
    fw::Framebuffer fb({w, h, "orientation"});
    fb.bind();
    clear_black();
    glEnable(GL_SCISSOR_TEST);
    glScissor(x, y, 1, 1);
    glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    fw::Image img = fb.read_color();
    bool pass = fw::test::probe_rgb(img, x, y, kRed);
    pass = fw::test::probe_rgb(img, x, h - 1 - y, kBlack) && pass;
    CHECK(pass);
    CHECK(count_pixels(img, {255, 0, 0, 255}) == 1);

    const std::string path = fw::test::out_dir() + "/orientation.png";
    fw::write_png(path, img);
    int pw = 0, ph = 0, channels = 0;
    unsigned char* png = stbi_load(path.c_str(), &pw, &ph, &channels, 4);
    REQUIRE(png != nullptr);
    CHECK(pw == w);
    CHECK(ph == h);
    auto red_at = [&](int row, int col) {
        const unsigned char* p = png + (static_cast<std::size_t>(row) * pw + col) * 4;
        return p[0] == 255 && p[1] == 0 && p[2] == 0;
    };
    // PNG rows run top to bottom, so window row y is PNG row H-1-y.
    CHECK_MESSAGE(red_at(h - 1 - y, x),
                  "expected red at PNG row " << h - 1 - y << ", column " << x);
    CHECK_MESSAGE(!red_at(y, x), "expected black at PNG row " << y << ", column " << x);
    stbi_image_free(png);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_CASE("framebuffer: a plane at NDC z = 0.5 reads back window depth 0.75") {
    // Window depth = (z_ndc + 1) / 2 with glDepthRange(0, 1).
    std::vector<ColorVertex> v = quad(-1, -1, 0, 1, 0.5f, kWhite);  // left half only
    fw::Buffer vbo = fw::Buffer::from(v, GL_ARRAY_BUFFER, "depth plane");
    fw::VertexArray vao({&vbo, color_layout(), nullptr, GL_UNSIGNED_INT, "depth plane"});
    fw::Program prog = fw::Program::from_files({"tests/color.vert", "tests/color.frag"});
    fw::Framebuffer fb({32, 32, "depth"});
    fb.bind();
    clear_black();
    glEnable(GL_DEPTH_TEST);
    prog.use();
    vao.draw(GL_TRIANGLES, 6);
    glDisable(GL_DEPTH_TEST);
    fw::check_gl("depth plane draw");
    fw::DepthImage depth = fb.read_depth();
    bool pass = fw::test::probe_depth(depth, 0, 0, 0.75f, 1e-6f);
    pass = fw::test::probe_depth(depth, 15, 31, 0.75f, 1e-6f) && pass;
    pass = fw::test::probe_depth(depth, 16, 16, 1.0f, 0.0f) && pass;  // cleared, not drawn
    CHECK(pass);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_CASE("framebuffer: 8 stencil bits mask a draw to where the stencil was set") {
    fw::Framebuffer fb({32, 32, "stencil"});
    fb.bind();
    GLint bits = 0;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT,
                                          GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &bits);
    CHECK(bits == 8);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    fw::Program prog = fw::Program::from_files({"tests/color.vert", "tests/color.frag"});
    prog.use();
    // Stencil 200 on the left half (a value above 1 needs more than one bit);
    // colour writes off while it is set.
    std::vector<ColorVertex> left = quad(-1, -1, 0, 1, 0, kRed);
    fw::Buffer left_vbo = fw::Buffer::from(left, GL_ARRAY_BUFFER, "stencil mask");
    fw::VertexArray mask({&left_vbo, color_layout(), nullptr, GL_UNSIGNED_INT, "stencil mask"});
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 200, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    mask.draw(GL_TRIANGLES, 6);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    // Green over the whole frame, only where the stencil is 200.
    std::vector<ColorVertex> all = quad(-1, -1, 1, 1, 0, kGreen);
    fw::Buffer all_vbo = fw::Buffer::from(all, GL_ARRAY_BUFFER, "stencil fill");
    fw::VertexArray fill({&all_vbo, color_layout(), nullptr, GL_UNSIGNED_INT, "stencil fill"});
    glStencilFunc(GL_EQUAL, 200, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    fill.draw(GL_TRIANGLES, 6);
    glDisable(GL_STENCIL_TEST);
    fw::check_gl("stencil draws");
    const fw::Image img = fb.read_color();
    bool pass = fw::test::probe_rgb(img, 4, 16, kGreen);
    pass = fw::test::probe_rgb(img, 27, 16, kBlack) && pass;
    CHECK(pass);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_CASE("framebuffer: a size of zero or above the GL limit names the field and the limit") {
    const auto zero = [] { fw::Framebuffer fb({0, 16, "zero"}); };
    check_mentions(thrown<fw::UsageError>(zero),
                   {"FramebufferDesc.width must be 1 to", "not 0", "'zero'"});
    const auto huge = [] { fw::Framebuffer fb({16, 1 << 20, "huge"}); };
    check_mentions(thrown<fw::UsageError>(huge),
                   {"FramebufferDesc.height must be 1 to", "GL_MAX_", "not 1048576"});
}

TEST_CASE("query: primitives generated and samples passed for a known draw") {
    // [-0.5, 0.5]^2 on a 64x64 target covers pixels 16..47 in x and y.
    std::vector<ColorVertex> v = quad(-0.5f, -0.5f, 0.5f, 0.5f, 0.0f, kWhite);
    fw::Buffer vbo = fw::Buffer::from(v, GL_ARRAY_BUFFER, "query quad");
    fw::VertexArray vao({&vbo, color_layout(), nullptr, GL_UNSIGNED_INT, "query quad"});
    fw::Program prog = fw::Program::from_files({"tests/color.vert", "tests/color.frag"});
    fw::Framebuffer fb({64, 64, "query"});
    fb.bind();
    clear_black();
    prog.use();
    fw::Query primitives(GL_PRIMITIVES_GENERATED, "primitives");
    fw::Query samples(GL_SAMPLES_PASSED, "samples");
    primitives.begin();
    samples.begin();
    vao.draw(GL_TRIANGLES, 6);
    samples.end();
    primitives.end();
    fw::check_gl("query draw");
    CHECK(primitives.result() == 2);
    CHECK(samples.result() == 32 * 32);

    check_mentions(thrown<fw::UsageError>([] { fw::Query q(GL_TEXTURE_2D); }),
                   {"GL_PRIMITIVES_GENERATED", "GL_SAMPLES_PASSED"});
    fw::Query unused(GL_SAMPLES_PASSED, "unused");
    check_mentions(thrown<fw::UsageError>([&] { unused.end(); }), {"end() without begin()"});
    check_mentions(thrown<fw::UsageError>([&] { (void)unused.result(); }), {"result() before"});
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_CASE("texture: create, bind and sample; data row 0 is the bottom row") {
    const std::vector<fw::Rgba8> texels = {{255, 0, 0, 255},
                                           {0, 255, 0, 255},  // bottom row: red, green
                                           {0, 0, 255, 255},
                                           {255, 255, 255, 255}};  // top row: blue, white
    fw::Texture2DDesc desc;
    desc.width = desc.height = 2;
    desc.data = texels.data();
    desc.min_filter = desc.mag_filter = GL_NEAREST;
    desc.label = "2x2";
    fw::Texture2D tex(desc);
    CHECK(fw::object_label(GL_TEXTURE, tex.id()) == "2x2");

    struct Vertex {
        glm::vec3 position;
        glm::vec2 uv;
    };
    std::vector<Vertex> v = {{{-1, -1, 0}, {0, 0}}, {{1, -1, 0}, {1, 0}}, {{1, 1, 0}, {1, 1}},
                             {{-1, -1, 0}, {0, 0}}, {{1, 1, 0}, {1, 1}},  {{-1, 1, 0}, {0, 1}}};
    fw::Buffer vbo = fw::Buffer::from(v, GL_ARRAY_BUFFER, "textured quad");
    fw::VertexArray vao(
        {&vbo,
         fw::VertexLayout::of<Vertex>().attr(kPosition, &Vertex::position).attr(kUv, &Vertex::uv),
         nullptr, GL_UNSIGNED_INT, "textured quad"});
    fw::Program prog = fw::Program::from_files({"tests/textured.vert", "tests/textured.frag"});
    constexpr GLuint kUnit = 1;
    tex.bind(kUnit);
    prog.set("u_texture", static_cast<int>(kUnit));
    fw::Framebuffer fb({32, 32, "texture"});
    fb.bind();
    clear_black();
    prog.use();
    vao.draw(GL_TRIANGLES, 6);
    fw::check_gl("textured draw");
    fw::Image img = fb.read_color();
    bool pass = fw::test::probe_rgb(img, 8, 8, kRed);
    pass = fw::test::probe_rgb(img, 24, 8, kGreen) && pass;
    pass = fw::test::probe_rgb(img, 8, 24, kBlue) && pass;
    pass = fw::test::probe_rgb(img, 24, 24, kWhite) && pass;
    CHECK(pass);
    glActiveTexture(GL_TEXTURE0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    fw::Texture2DDesc bad;
    bad.label = "bad";
    check_mentions(thrown<fw::UsageError>([&] { fw::Texture2D t(bad); }),
                   {"Texture2DDesc.width must be 1 to GL_MAX_TEXTURE_SIZE", "'bad'"});
    bad.width = bad.height = 4;
    bad.internal_format = GL_RGBA;  // unsized: glTexStorage2D refuses it
    check_mentions(thrown<fw::UsageError>([&] { fw::Texture2D t(bad); }),
                   {"Texture2DDesc.internal_format", "sized format"});
    drain_gl_errors();
}

TEST_CASE("check_gl: a provoked error reports GL's message and the bound objects' labels") {
    fw::enable_debug_output();
    drain_gl_errors();
    std::vector<ColorVertex> v = quad(-1, -1, 1, 1, 0, kWhite);
    fw::Buffer vbo = fw::Buffer::from(v, GL_ARRAY_BUFFER, "check quad");
    fw::VertexArray vao({&vbo, color_layout(), nullptr, GL_UNSIGNED_INT, "check quad"});
    fw::Program prog = fw::Program::from_files({"tests/color.vert", "tests/color.frag"});
    fw::Framebuffer fb({16, 16, "checked target"});
    fb.bind();
    prog.use();
    vao.bind();
    CHECK_NOTHROW(fw::check_gl("clean state"));

    glBindBuffer(0x1234, 0);  // not a buffer target: GL_INVALID_ENUM
    check_mentions(thrown([] { fw::check_gl("deliberate glBindBuffer"); }),
                   {"GL error after deliberate glBindBuffer: GL_INVALID_ENUM", "glBindBuffer",
                    "program 'tests/color.vert + color.frag'", "vertex array 'check quad'",
                    "framebuffer 'checked target'"});
    CHECK_NOTHROW(fw::check_gl("after the error was reported"));
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}
