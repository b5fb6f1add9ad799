// Mistakes of other kinds than the suite's, planted in a shader (no rebuild:
// the built `lab` reads LAB_SHADER_DIR), whose frame is the frame of a
// mistake the course knows: the grader must not name the known mistake, and
// must say why it is not that one, from this submission's own evidence
// (grading/diagnosis/frame_guesses.hpp). Each plant is graded with `course
// grade` on the backend of the test (LAB_BACKEND).
#include <filesystem>
#include <string>

#include "framework/text.hpp"
#include "tests/grading/tree_support.hpp"
#include "tests/support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using fw::shell_quote;
using tree_test::Grade;

// Grades `lab` with `file` (under shaders/) changed from `find` to
// `replace`, in a copy of the shaders.
Grade graded_with(const std::string& lab, const std::string& file, const std::string& find,
                  const std::string& replace, const std::string& name) {
    const fs::path dir = fs::path(fw::test::out_dir()) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy(fs::path(fw::test::source_dir()) / "shaders", dir / "shaders",
             fs::copy_options::recursive);
    const fs::path target = dir / "shaders" / file;
    std::string text = fw::test::read_text(target.string());
    const size_t at = text.find(find);
    REQUIRE_MESSAGE(at != std::string::npos, file << " no longer holds: " << find);
    text.replace(at, find.size(), replace);
    fw::test::write_text(target.string(), text);
    return tree_test::grade(fw::test::bin_dir() + "/course", fw::test::bin_dir() + "/lab", lab,
                            dir / "out",
                            "LAB_SHADER_DIR=" + shell_quote((dir / "shaders").string()));
}

}  // namespace

TEST_CASE("planted: a translation negated in the shader is not the known negated translate()") {
    // transforms-translate-negated's frame at `translate`, drawn by a vertex
    // shader that negates the model matrix's translation: translate() itself
    // passes its unit check, so the grader must not name that mistake.
    const Grade g =
        graded_with("transforms", "01_transforms/transforms.vert",
                    "gl_Position = u_projection * u_model * vec4(a_position, 0.0, 1.0);",
                    "mat4 m = u_model;\n    m[3].xy = -m[3].xy;\n"
                    "    gl_Position = u_projection * m * vec4(a_position, 0.0, 1.0);",
                    "negated-in-shader");
    INFO(g.output);
    CHECK(g.exit_code == 1);
    CHECK(g.output.find("known mistake draws (transforms-translate-negated)") == std::string::npos);
    CHECK(g.output.find("The frame also matches a known mistake (transforms-translate-negated), "
                        "but your `") != std::string::npos);
    CHECK(g.output.find("()` passes its unit check, which transforms-translate-negated fails") !=
          std::string::npos);
}

TEST_CASE("planted: an alpha inverted in the shader is not the known swapped blend factors") {
    // framebuffer-ops-over-factors-swapped's frame at `blend_over`, drawn with
    // the sheet's glBlendFunc by a fragment shader that writes 1 - alpha: the
    // state diff finds the solution's blend state, so the grader must not
    // name the swapped factors.
    const Grade g = graded_with(
        "framebuffer-ops", "07_framebuffer_ops/solid.frag", "void main() { frag_color = u_color; }",
        "void main() { frag_color = vec4(u_color.rgb, 1.0 - u_color.a); }", "alpha-inverted");
    INFO(g.output);
    CHECK(g.exit_code == 1);
    CHECK(g.output.find("known mistake draws (framebuffer-ops-over-factors-swapped)") ==
          std::string::npos);
    CHECK(g.output.find("The frame also matches a known mistake "
                        "(framebuffer-ops-over-factors-swapped), but your draws are told the "
                        "state the solution's are") != std::string::npos);
}
