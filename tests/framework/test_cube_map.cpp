// The wrapper's cube maps: fw::TextureCube's storage and its errors, and
// fw::CubeFramebuffer's layered colour and depth attachments, drawn into
// through a geometry shader that writes gl_Layer. Runs once per backend.
#include <glad/gl.h>

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/gl.hpp"
#include "tests/support/test_support.hpp"

namespace {

using fw::test::check_mentions;
using fw::test::thrown;

// What shaders/tests/layers.geom writes into face f.
glm::vec3 face_color(int f) { return {float(f & 1), float((f >> 1) & 1), f >= 4 ? 1.0f : 0.5f}; }

}  // namespace

TEST_CASE("cube map: storage for six faces, labelled, and its descriptor's errors named") {
    fw::enable_debug_output();
    fw::TextureCube cube(fw::TextureCubeDesc{.size = 8, .label = "sky"});
    CHECK(cube.size() == 8);
    CHECK(cube.internal_format() == GL_RGBA8);
    CHECK(fw::object_label(GL_TEXTURE, cube.id()) == "sky");
    GLint width = 0;
    cube.bind(0);
    glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_TEXTURE_WIDTH, &width);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    CHECK(width == 8);
    check_mentions(thrown<fw::UsageError>([] { fw::TextureCube({.size = 0, .label = "none"}); }),
                   {"TextureCubeDesc.size", "GL_MAX_CUBE_MAP_TEXTURE_SIZE", "'none'"});
    check_mentions(thrown<fw::UsageError>([] {
                       fw::TextureCube({.size = 4, .internal_format = GL_RGBA, .label = "unsized"});
                   }),
                   {"TextureCubeDesc.internal_format", "GL_RGBA8", "'unsized'"});
    check_mentions(
        thrown<fw::UsageError>([] {
            fw::TextureCube({.size = 4, .min_filter = GL_LINEAR_MIPMAP_LINEAR, .label = "mips"});
        }),
        {"TextureCubeDesc.min_filter", "'mips'"});
    check_mentions(thrown<fw::UsageError>([&] { cube.read_face(6); }), {"face", "0 to 5", "'sky'"});
    while (glGetError() != GL_NO_ERROR) {
    }
    fw::take_debug_messages();
}

TEST_CASE("cube framebuffer: one draw reaches all six faces, each with its own depth") {
    fw::enable_debug_output();
    fw::CubeFramebuffer cube({16, "six faces"});
    CHECK(fw::object_label(GL_FRAMEBUFFER, cube.id()) == "six faces");
    CHECK(fw::object_label(GL_TEXTURE, cube.color_texture().id()) == "six faces colour");
    CHECK(fw::object_label(GL_TEXTURE, cube.depth_texture().id()) == "six faces depth");
    CHECK(cube.depth_texture().internal_format() == GL_DEPTH_COMPONENT32F);

    // One triangle covering the whole face.
    const std::vector<glm::vec3> triangle = {{-1, -1, 0}, {3, -1, 0}, {-1, 3, 0}};
    fw::Buffer vertices = fw::Buffer::from(triangle, GL_ARRAY_BUFFER, "covering triangle");
    fw::VertexArray vao(fw::VertexArrayDesc{
        .vertices = &vertices,
        .layout = fw::VertexLayout(sizeof(glm::vec3)).add({0, 3, GL_FLOAT, 0, false, false}),
        .label = "covering triangle"});
    fw::Program program =
        fw::Program::from_files({"tests/position.vert", "tests/layers.geom", "tests/color.frag"});

    cube.bind();
    GLint viewport[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_VIEWPORT, viewport);
    CHECK(viewport[2] == 16);
    CHECK(viewport[3] == 16);
    // glClear clears every layer of a layered framebuffer.
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    program.use();
    glBindVertexArray(vao.id());
    // The faces' colours at depth 0.5, then white behind them at 0.8: the
    // depth test of each face must keep the colours.
    program.set("u_white", false);
    program.set("u_depth", 0.5f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    program.set("u_white", true);
    program.set("u_depth", 0.8f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    fw::check_gl("after the layered draws");

    for (int face = 0; face < 6; ++face) {
        INFO("face " << face);
        const fw::Image img = cube.color_texture().read_face(face);
        REQUIRE(img.width == 16);
        bool pass = fw::test::probe_rgb(img, 8, 8, face_color(face));
        pass = fw::test::probe_rgb(img, 0, 15, face_color(face)) && pass;
        CHECK(pass);
    }
}
