// Shader file handling that needs no GL context: stages from extensions,
// shader paths, and the compile error text built from a driver's log.
#include <cstdlib>
#include <string>
#include <vector>

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
    CHECK(fw::shader_path("00_pipeline/pipeline.vert") ==
          fw::test::source_dir() + "/shaders/00_pipeline/pipeline.vert");
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

TEST_CASE("shader text: #include pastes a file of the same folder between #line directives") {
    const std::string dir = fw::test::out_dir();
    fw::test::write_text(dir + "/shared.glsl", "// names\n#define A_POSITION 0\n");
    std::vector<fw::IncludedFile> included;
    const std::string expanded = fw::expand_includes(
        "#version 430 core\n#include \"shared.glsl\"\nlayout(location = A_POSITION) in vec3 p;\n",
        dir + "/x.vert", included);
    MESSAGE(expanded);
    // The included file is source string 1 from line 100001; after it, the
    // shader's own numbering resumes at line 3 of string 0.
    CHECK(expanded ==
          "#version 430 core\n"
          "#line 100001 1\n// names\n#define A_POSITION 0\n\n#line 3 0\n"
          "layout(location = A_POSITION) in vec3 p;\n");
    REQUIRE(included.size() == 1);
    // Messages show paths inside the source tree relative to it.
    const std::string shown = fw::display_path(dir + "/shared.glsl");
    CHECK(included[0].path == shown);
    CHECK(included[0].text == "// names\n#define A_POSITION 0\n");

    // A log line of string 1 (NVIDIA) or of line 100002 (Mesa, which says
    // string 0) quotes the included file's own line.
    for (const char* log : {"1(2) : error C0000: syntax error\n", "0:100002(9): error: syntax\n"}) {
        const std::string error =
            fw::format_compile_error("x.vert", fw::Stage::Vertex, log,
                                     "#version 430 core\n#include \"shared.glsl\"\n", included);
        MESSAGE(error);
        CHECK(error.find(shown + ":2: vertex shader failed to compile:") == 0);
        CHECK(error.find("  " + shown + ":2 | #define A_POSITION 0") != std::string::npos);
    }
}

TEST_CASE("shader text: a bad #include names the line and the file") {
    const std::string dir = fw::test::out_dir();
    std::vector<fw::IncludedFile> included;
    auto error = [&](const std::string& text) {
        return fw::test::thrown([&] { fw::expand_includes(text, dir + "/y.frag", included); });
    };
    fw::test::check_mentions(error("#version 430 core\n#include \"missing.glsl\"\n"),
                             {fw::display_path(dir + "/y.frag") + ":2:",
                              "cannot read included file", dir + "/missing.glsl"});
    fw::test::check_mentions(error("#include <shared.glsl>\n"), {"y.frag:1:", "#include \"name\""});
    fw::test::check_mentions(error("#include \"../other/shared.glsl\"\n"),
                             {"y.frag:1:", "same folder"});
    fw::test::write_text(dir + "/outer.glsl", "#include \"inner.glsl\"\n");
    fw::test::check_mentions(error("#include \"outer.glsl\"\n"),
                             {"outer.glsl", "may not include another"});
}
