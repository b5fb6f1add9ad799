// Shader file handling that needs no GL context: stages from extensions,
// shader paths, and the compile error text built from a driver's log.
#include <cstdlib>
#include <string>

#include "framework/error.hpp"
#include "framework/gl/shader.hpp"
#include "tests/support/test_support.hpp"

TEST_CASE("shader text: the stage comes from the extension") {
    CHECK(fw::stage_from_path("a/b.vert") == fw::Stage::Vertex);
    CHECK(fw::stage_from_path("b.tesc") == fw::Stage::TessControl);
    CHECK(fw::stage_from_path("b.tese") == fw::Stage::TessEvaluation);
    CHECK(fw::stage_from_path("b.geom") == fw::Stage::Geometry);
    CHECK(fw::stage_from_path("b.frag") == fw::Stage::Fragment);
    CHECK(fw::stage_from_path("b.comp") == fw::Stage::Compute);
    CHECK_THROWS_AS(fw::stage_from_path("b.glsl"), fw::UsageError);
    CHECK(std::string(fw::stage_name(fw::Stage::TessControl)) == "tessellation control");
}

TEST_CASE("shader text: paths resolve against LAB_SHADER_DIR, else the source tree") {
    unsetenv("LAB_SHADER_DIR");
    CHECK(fw::shader_path("00_pipeline/basic.vert") ==
          fw::test::source_dir() + "/shaders/00_pipeline/basic.vert");
    CHECK(fw::shader_path("/abs/x.frag") == "/abs/x.frag");
    setenv("LAB_SHADER_DIR", "/tmp/my shaders", 1);
    CHECK(fw::shader_path("a.vert") == "/tmp/my shaders/a.vert");
    unsetenv("LAB_SHADER_DIR");
    CHECK(fw::display_path(fw::test::source_dir() + "/shaders/tests/broken.frag") ==
          "shaders/tests/broken.frag");
}

TEST_CASE("shader text: line numbers from Mesa, NVIDIA and other logs") {
    CHECK(fw::log_line_number("0:12(5): error: `foo' undeclared") == 12);
    CHECK(fw::log_line_number("0(12) : error C1008: undefined variable \"foo\"") == 12);
    CHECK(fw::log_line_number("ERROR: 0:7: 'foo' : undeclared identifier") == 7);
    CHECK(fw::log_line_number("error: linking failed") == 0);
}

TEST_CASE("shader text: a compile error quotes each line the log names, once") {
    const std::string source = "#version 430 core\nout vec4 o;\nvoid main() {\n    o = foo;\n}\n";
    const std::string mesa = fw::format_compile_error(
        "shaders/x.frag", fw::Stage::Fragment,
        "0:4(9): error: `foo' undeclared\n0:4(5): error: type mismatch\n", source);
    MESSAGE(mesa);
    CHECK(mesa ==
          "shaders/x.frag:4: fragment shader failed to compile:\n"
          "  0:4(9): error: `foo' undeclared\n"
          "  4 |     o = foo;\n"
          "  0:4(5): error: type mismatch\n");
    const std::string nvidia = fw::format_compile_error(
        "x.geom", fw::Stage::Geometry, "0(4) : error C1008: undefined variable \"foo\"\n", source);
    MESSAGE(nvidia);
    CHECK(nvidia.find("x.geom:4: geometry shader failed to compile:") == 0);
    CHECK(nvidia.find("  4 |     o = foo;") != std::string::npos);
    // A log without line numbers still names the file and stage.
    const std::string bare =
        fw::format_compile_error("x.vert", fw::Stage::Vertex, "internal error\n", source);
    CHECK(bare == "x.vert: vertex shader failed to compile:\n  internal error\n");
}
