// Shared by every test: the GL context a GL test runs in, and piglit-style
// probes that print Expected/Observed for every probe, passing or not.
#pragma once

#include <doctest/doctest.h>

#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <utility>
#include <vector>

#include "framework/checkpoints.hpp"
#include "framework/context.hpp"
#include "framework/error.hpp"
#include "framework/image.hpp"
#include "framework/render.hpp"

namespace fw::test {

// The context of a GL test (LAB_BACKEND selects it; tests/CMakeLists.txt runs
// each GL test once per backend). Only valid in tests built with lab_gl_test.
const ContextInfo& context_info();

// Whether LAB_REQUIRE_BACKENDS (CI sets it) asks for `backend`: the variable
// is a comma-separated list of names, or "built" for every backend this build
// has (egl always, osmesa when CMake found it). A required backend that does
// not work here fails the test instead of skipping it.
bool backend_required(const std::string& backend);
// For a part of a test case that needs `backend`, which does not work here
// (`why`): fails the test case when the backend is required; otherwise prints
// "SKIP <what> (backend <backend>): <why>" so that the reason shows in the
// test's output, and the caller leaves that part out and runs the rest.
void skip_part_without(const std::string& backend, const std::string& what, const std::string& why);

// Directory for files a test writes, created: build/test-out/<test name>/,
// or build/test-out/<backend>/<test name>/ when $LAB_BACKEND names one.
std::string out_dir();
// Marks `path` (a file or a folder) for removal when this test executable
// ends with every test case passed: a passing suite leaves no copied trees,
// builds or staged folders behind; a failing one keeps them for a look.
// LAB_KEEP_TEST_OUT=1 keeps them either way. main() does the removing.
void remove_when_passed(const std::string& path);
// main()'s part: removes what remove_when_passed marked when `passed`, and
// says on stdout how much it freed.
void remove_marked(bool passed);
// The build's bin directory (where `lab` lives) and the source tree.
std::string bin_dir();
std::string source_dir();

// Colour probe: pixel (x, y) in GL window coordinates (origin bottom-left)
// within `tol` (0..1, per channel, RGB only) of `expected`. Logs
// "probe (x, y): expected (r, g, b) observed (r, g, b)" and returns pass.
bool probe_rgb(const Image& img, int x, int y, glm::vec3 expected, float tol = 1.0f / 255.0f);
// Depth probe, window-space depth in [0, 1].
bool probe_depth(const DepthImage& img, int x, int y, float expected, float tol = 1e-5f);

// The probe and stat checks of a checkpoint, as its data file writes them,
// against a frame rendered here: colour probes ("at", "color", "tolerance"),
// depth probes ("at", "depth", "tolerance") and stats ("stat" as a dotted path
// into the stats, "equals"). Other kinds are left to the caller. A lab test
// uses it to show that the file's expectations hold for the solution.
void check_probes_and_stats(const nlohmann::json& checks, const RenderOutput& out);

// The lab whose folder the test is in: a lab's test (labs/NN_name/tests/)
// tests the lab of its own folder, so that a copy of the lab under another
// name tests the copy. Only in lab tests (tests/support/this_lab.cpp).
const RegisteredLab& this_lab();

// A lab and its renderer in the test's context, created once per test case.
using Settings = std::vector<std::pair<std::string, std::string>>;  // name, value as --set takes it
struct LabUnderTest {
    LabUnderTest();  // this_lab(); only in lab tests
    explicit LabUnderTest(const RegisteredLab& lab);
    explicit LabUnderTest(const std::string& id);
    // The defaults, then `settings`.
    ParamValues params(const Settings& settings) const;
    RenderOutput render(const Settings& settings, int width = 512, int height = 512);

    const RegisteredLab& lab;
    LabRenderer renderer;
};

// Pixel (x, y) of `img` as (r, g, b) in [0, 1]; whether two colours are
// within `tol` on every channel.
glm::vec3 rgb_at(const Image& img, int x, int y);
bool near(glm::vec3 a, glm::vec3 b, float tol);

// Renders every checkpoint of the lab's data file at 512 x 512 and hands each,
// with its resolved parameters and the frame, to `visit` (the checkpoint's
// name is captured for every check made there). Checks that the file has at
// least `min_count` checkpoints and that some, but not all, are hidden.
using CheckpointVisitor =
    std::function<void(const Checkpoint&, const ParamValues&, const RenderOutput&)>;
void for_each_checkpoint(const RegisteredLab& lab, LabRenderer& renderer, size_t min_count,
                         const CheckpointVisitor& visit);

// The message of the E that `f` throws; a failed check if it throws nothing
// (or something else, which then propagates).
template <class E = fw::Error, class F>
std::string thrown(F&& f) {
    try {
        f();
    } catch (const E& e) {
        return e.what();
    }
    FAIL_CHECK("expected an exception; none was thrown");
    return {};
}

// Logs `message` and checks that it contains every one of `needles`.
void check_mentions(const std::string& message, const std::vector<std::string>& needles);

// Files for tests that run commands on copies of the tree (fw::shell_quote,
// framework/text.hpp, makes their shell words).
std::string read_text(const std::string& path);                     // "" when unreadable
void write_text(const std::string& path, const std::string& text);  // makes the parent folders

// Runs a command through /bin/sh, capturing stdout and stderr together.
struct CommandResult {
    int exit_code = -1;  // -1: did not exit normally
    std::string output;
};
CommandResult run_command(const std::string& command);

}  // namespace fw::test

// Pixels print as "rgba(255, 0, 0, 255)" in a failed CHECK.
template <>
struct doctest::StringMaker<fw::Rgba8> {
    static doctest::String convert(const fw::Rgba8& p) {
        const std::string s = "rgba(" + std::to_string(p.r) + ", " + std::to_string(p.g) + ", " +
                              std::to_string(p.b) + ", " + std::to_string(p.a) + ")";
        return s.c_str();
    }
};
