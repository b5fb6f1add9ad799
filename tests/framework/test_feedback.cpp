// The wrapper's parts for what shaders write into buffers: a program linked
// with captured outputs and a TransformFeedback object, a compute program
// over a storage buffer. Runs once per backend.
#include <glad/gl.h>

#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/gl.hpp"
#include "tests/support/test_support.hpp"

namespace {

using fw::test::check_mentions;
using fw::test::thrown;

struct Value {
    glm::vec3 v;
};

struct Captured {
    glm::vec3 doubled;
    float index;
};

}  // namespace

TEST_CASE("transform feedback: captured outputs are interleaved in the order given") {
    fw::enable_debug_output();
    const std::vector<Value> values = {{{1, 2, 3}}, {{-4, 0.5f, 8}}, {{0, 0, -1}}};
    fw::Buffer input = fw::Buffer::from(values, GL_ARRAY_BUFFER, "values");
    fw::VertexArray vao(
        fw::VertexArrayDesc{.vertices = &input,
                            .layout = fw::VertexLayout::of<Value>().attr(0, &Value::v),
                            .label = "values"});
    fw::BufferDesc desc;
    desc.size = values.size() * sizeof(Captured);
    desc.usage = GL_STREAM_READ;
    desc.label = "captured";
    fw::Buffer captured(desc);
    fw::Program program = fw::Program::from_files({"tests/feedback.vert", "tests/white.frag"}, {},
                                                  {"v_doubled", "v_index"});
    CHECK(program.feedback() == std::vector<std::string>{"v_doubled", "v_index"});
    fw::TransformFeedback feedback("doubling");
    CHECK(fw::object_label(GL_TRANSFORM_FEEDBACK, feedback.id()) == "doubling");
    fw::Query written(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, "written");

    // Nothing is rasterized, but a draw still needs a complete framebuffer.
    fw::Framebuffer fb({4, 4, "feedback"});
    fb.bind();
    program.use();
    glBindVertexArray(vao.id());
    glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, feedback.id());
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, captured.id());
    glEnable(GL_RASTERIZER_DISCARD);
    written.begin();
    glBeginTransformFeedback(GL_POINTS);
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(values.size()));
    glEndTransformFeedback();
    written.end();
    glDisable(GL_RASTERIZER_DISCARD);
    glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    fw::check_gl("after the capture");

    CHECK(written.result() == values.size());
    const std::vector<Captured> out = captured.read_as<Captured>();
    REQUIRE(out.size() == values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        INFO("vertex " << i);
        CHECK(out[i].doubled == 2.0f * values[i].v);
        CHECK(out[i].index == static_cast<float>(i));
    }
}

TEST_CASE("transform feedback: an output the stage does not write fails the link, named") {
    fw::enable_debug_output();
    const std::string msg = thrown<fw::ShaderError>([] {
        fw::Program::from_files({"tests/feedback.vert", "tests/white.frag"}, {},
                                {"v_doubled", "v_tripled"});
    });
    check_mentions(msg, {"failed to link", "tests/feedback.vert", "v_tripled"});
    CHECK_NOTHROW(fw::check_gl("after the failed link"));
    // The program library keeps the names for a reload.
    fw::ProgramLibrary programs("tests");
    fw::Program& p = programs.load({"feedback.vert", "white.frag"}, {"v_index"});
    CHECK(p.build_error() == nullptr);
    CHECK(programs.reload_all().empty());
    CHECK(p.feedback() == std::vector<std::string>{"v_index"});
}

TEST_CASE("compute: a program of one compute stage runs over a storage buffer") {
    fw::enable_debug_output();
    // Ten values in work groups of four: three groups, the last one partly idle.
    std::vector<float> values(10);
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<float>(i);
    fw::Buffer storage = fw::Buffer::from(values, GL_SHADER_STORAGE_BUFFER, "values");
    fw::Program program = fw::Program::from_files({"tests/double.comp"});
    program.use();
    program.set("u_count", 10u);
    storage.bind_base(0);
    glDispatchCompute(3, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    fw::check_gl("after the dispatch");
    const std::vector<float> out = storage.read_as<float>();
    REQUIRE(out.size() == values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        INFO("value " << i);
        CHECK(out[i] == 2.0f * values[i] + static_cast<float>(i / 4));
    }
}
