// What a lab's shaders wrote, read back after the frame (Lab::buffers): the
// renderer asks only when told (ReadBack), in the frame's context, with the
// frame the draw saw; a lab's malformed buffers are an error naming it; the
// buffers file reads back the floats the lab returned.
#include <glad/gl.h>

#include <memory>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/lab_buffers.hpp"
#include "framework/render.hpp"
#include "tests/support/test_support.hpp"

namespace {

// Draws nothing; its one GL buffer holds (width, height, draws so far),
// written in draw() and read back with glGetBufferSubData.
class ReadbackLab : public fw::Lab {
public:
    static int components;  // what buffers() claims, for the error case
    ~ReadbackLab() override {
        if (buffer_) glDeleteBuffers(1, &buffer_);
    }
    void init(fw::ProgramLibrary&) override { glGenBuffers(1, &buffer_); }
    void draw(const fw::ParamValues&, const fw::Frame& frame) override {
        ++draws_;
        const float values[3] = {float(frame.width), float(frame.height), float(draws_)};
        glBindBuffer(GL_ARRAY_BUFFER, buffer_);
        glBufferData(GL_ARRAY_BUFFER, sizeof values, values, GL_DYNAMIC_DRAW);
    }
    std::vector<fw::LabBuffer> buffers(const fw::ParamValues&,
                                       const fw::Frame& frame) const override {
        std::vector<float> values(3);
        glBindBuffer(GL_ARRAY_BUFFER, buffer_);
        glGetBufferSubData(GL_ARRAY_BUFFER, 0, sizeof(float) * 3, values.data());
        values.push_back(float(frame.width));
        return {{"state", components, values}};
    }

private:
    GLuint buffer_ = 0;
    int draws_ = 0;
};
int ReadbackLab::components = 4;

const fw::RegisteredLab& readback_lab() {
    static const bool registered = [] {
        fw::LabInfo info;
        info.title = "buffers read back";
        info.aspect = 1.0;
        return fw::register_lab("90_readback", info,
                                [] { return std::make_unique<ReadbackLab>(); });
    }();
    REQUIRE(registered);
    return fw::find_lab("readback");
}

}  // namespace

TEST_CASE("the renderer reads the lab's buffers back after the frame, only when asked") {
    fw::LabRenderer renderer(readback_lab(), fw::test::context_info());
    const fw::ParamValues params = fw::default_params(readback_lab());
    const fw::RenderOutput plain = renderer.render(params, 64, 32);
    CHECK(plain.buffers.empty());
    CHECK(plain.depth.width == 64);
    // A frame of another shape: the lab sees the square part it draws into.
    const fw::RenderOutput out = renderer.render(params, 64, 32, 0.0, fw::ReadBack{false, true});
    CHECK(out.depth.width == 0);
    REQUIRE(out.buffers.size() == 1);
    CHECK(out.buffers[0].name == "state");
    CHECK(out.buffers[0].values == std::vector<float>{32, 32, 2, 32});
    const std::vector<fw::LabBuffer> read =
        fw::parse_buffers(fw::buffers_json(out.buffers), "state.buffers.json");
    REQUIRE(read.size() == 1);
    CHECK(read[0].values == out.buffers[0].values);

    ReadbackLab::components = 0;
    CHECK_THROWS_WITH_AS(renderer.render(params, 64, 32, 0.0, fw::ReadBack{false, true}),
                         doctest::Contains("lab 'readback': buffers(): LabBuffer 'state': "
                                           "components is 0"),
                         fw::Error);
    ReadbackLab::components = 4;
}
