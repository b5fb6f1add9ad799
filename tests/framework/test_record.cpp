// framework/trace/record: what a draw was told, on a real context: the state
// that decides its result is there, state that cannot change it is not, no
// GL object is named by its number, and the same calls give the same text.
#include <glad/gl.h>

#include "framework/trace/record.hpp"
#include "tests/framework/record_scene.hpp"
#include "tests/support/test_support.hpp"

using nlohmann::json;
using record_test::Scene;

namespace {

// The one draw of a record.
json the_draw(const json& record) {
    REQUIRE(record.at("version") == fw::gl_record::kVersion);
    for (const json& e : record.at("events"))
        if (e.at("call") == "glDrawArrays") return e;
    FAIL("no draw in the record: " << record.dump());
    return {};
}

}  // namespace

TEST_CASE("record: a draw's call, program, uniforms, attributes and texture are there") {
    Scene scene;
    const json draw = the_draw(scene.record([&] { scene.draw(); }));
    CHECK(draw["args"] == json{{"mode", "GL_TRIANGLES"}, {"first", 0}, {"count", 3}});
    CHECK(draw["program"] == "record/scene.vert + scene.frag");
    // Active uniforms only: u_unused is declared, never read.
    CHECK(draw["uniforms"] == json{{"u_color", {1, 0.5, 0.25, 0.5}}, {"u_texture", 0}});
    // The attribute the program reads, by its buffer's creation order (no label).
    const json attributes = draw["vertex_array"]["attributes"];
    CHECK(draw["vertex_array"]["label"] == "triangle");
    REQUIRE(attributes.size() == 1);
    CHECK(attributes["0"]["name"] == "a_position");
    CHECK(attributes["0"]["stride"] == 12);
    CHECK(attributes["0"]["buffer"] == "buffer #1");
    const json unit = draw["textures"]["0"];
    CHECK(unit["texture"] == "white");
    CHECK(unit["wrap_s"] == "GL_REPEAT");
    CHECK(unit["min_filter"] == "GL_LINEAR");
    CHECK_FALSE(unit.contains("levels"));  // a filter without mipmaps reads level 0 only
    CHECK(draw["viewport"] == json{0, 0, 64, 64});
}

TEST_CASE("record: state the draw's result cannot depend on is left out") {
    Scene scene;
    const json draw = the_draw(scene.record([&] {
        // Set but not live: every test off.
        glBlendFunc(GL_SRC_ALPHA, GL_DST_ALPHA);
        glDepthFunc(GL_GREATER);
        glDepthMask(GL_FALSE);
        glStencilFunc(GL_NOTEQUAL, 1, 0xFF);
        glScissor(1, 2, 3, 4);
        glCullFace(GL_FRONT);
        scene.draw();
    }));
    CHECK(draw["enabled"] == json::array());
    for (const char* dead : {"blend", "depth", "stencil", "scissor", "cull"})
        CHECK_MESSAGE(!draw.contains(dead), dead << " is recorded with its test off");
    // With the rasterizer off, no fragment state at all.
    const json discarded = the_draw(scene.record([&] {
        glEnable(GL_RASTERIZER_DISCARD);
        glEnable(GL_BLEND);
        scene.draw();
    }));
    CHECK(discarded["enabled"] == json{"GL_RASTERIZER_DISCARD", "GL_BLEND"});
    for (const char* dead : {"blend", "viewport", "color_mask", "framebuffer"})
        CHECK_MESSAGE(!discarded.contains(dead), dead << " is recorded with the rasterizer off");
}

TEST_CASE("record: the tests' state is there once they are on") {
    Scene scene;
    const json draw = the_draw(scene.record([&] {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glEnable(GL_DEPTH_TEST);
        glDepthMask(GL_FALSE);
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_EQUAL, 1, 0xFF);
        glEnable(GL_SCISSOR_TEST);
        glScissor(8, 8, 16, 16);
        glEnable(GL_CLIP_DISTANCE0);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
        scene.draw();
    }));
    CHECK(draw["enabled"] == json{"GL_BLEND", "GL_DEPTH_TEST", "GL_STENCIL_TEST", "GL_SCISSOR_TEST",
                                  "GL_CLIP_DISTANCE0"});
    // Alpha is not written: its factors are not live.
    CHECK(draw["blend"] == json{{"src_rgb", "GL_SRC_ALPHA"},
                                {"dst_rgb", "GL_ONE_MINUS_SRC_ALPHA"},
                                {"equation_rgb", "GL_FUNC_ADD"}});
    CHECK(draw["depth"]["mask"] == false);
    CHECK(draw["depth"]["func"] == "GL_LESS");
    CHECK(draw["stencil"]["func"] == "GL_EQUAL");
    CHECK(draw["scissor"] == json{8, 8, 16, 16});
}

TEST_CASE("record: values, not calls: equal state written another way gives the same text") {
    Scene scene;
    const auto text = [&](auto calls) { return fw::gl_record::record_text(scene.record(calls)); };
    const std::string plain = text([&] {
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        scene.draw();
    });
    const std::string separate = text([&] {
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA,
                            GL_ONE_MINUS_SRC_ALPHA);
        glBlendEquationSeparate(GL_FUNC_ADD, GL_FUNC_ADD);
        glEnable(GL_BLEND);
        scene.draw();
    });
    CHECK(plain == separate);
    CHECK(text([&] {
              glEnable(GL_BLEND);
              glBlendEquation(GL_FUNC_ADD);
              glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
              scene.draw();
          }) == plain);
    CHECK(plain.find("\n{\"args\"") != std::string::npos);  // one event a line
    CHECK(plain.rfind("{\"version\": 1, \"events\": [\n", 0) == 0);
}

TEST_CASE("record: mipmap levels, a clear's state and what is not recorded before begin") {
    Scene scene;
    const json levels = the_draw(scene.record([&] {
        glBindTexture(GL_TEXTURE_2D, scene.texture);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        scene.draw();
    }));
    CHECK(levels["textures"]["0"]["levels"] == 1);
    const json clear = scene.record([&] {
        glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    });
    REQUIRE(clear["events"].size() == 1);
    const json& c = clear["events"][0];
    CHECK(c["args"]["mask"] == "GL_COLOR_BUFFER_BIT");
    CHECK(c["clear_color"] == json{0.25, 0.5, 0.75, 1});
    CHECK_FALSE(c.contains("clear_depth"));  // depth is not cleared
    scene.draw();                            // after end(): not recorded
    CHECK(scene.recorder.end()["events"].empty());
}
