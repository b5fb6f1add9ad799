// `lab run` (docs/contract.md, `lab`): under Xvfb the window shows exactly what
// `lab render` draws offscreen, the panel draws on top of it, and without a
// display the error says what is missing and what to run instead. A driver
// without GL 4.3 core (imitated with Mesa's override variables) makes the
// window fall back to the software renderer, or fail naming `lab serve`.
// Each case runs the real `lab` executable as a child process.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "framework/image.hpp"
#include "tests/support/test_support.hpp"

#ifndef LAB_HAVE_WINDOW
#define LAB_HAVE_WINDOW 0
#endif

namespace {

std::string lab() { return fw::test::bin_dir() + "/lab"; }

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

int occurrences(const std::string& text, const std::string& part) {
    int n = 0;
    for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

// Mesa reports the version MESA_GL_VERSION_OVERRIDE names, so the window's 4.3
// core request fails as it does on a driver that offers only GL 4.1.
const std::string kOldDriver = "MESA_GL_VERSION_OVERRIDE=4.1";
const std::string kSoftwareLine =
    "Software rendering (llvmpipe): the GPU driver offers only OpenGL 4.1";

fw::test::CommandResult run(const std::string& cmd) {
    fw::test::CommandResult r = fw::test::run_command(cmd);
    MESSAGE("$ " << cmd << "\nexit " << r.exit_code << "\n" << r.output);
    return r;
}

// Skips the whole test (exit 77, which CTest reports as skipped) when this
// machine or build cannot run windows. Every case calls it first, so the skip
// happens before any case has run and no failure can be hidden by it.
void require_window_support() {
    auto skip = [](const char* why) {
        std::printf("SKIP: %s\n", why);
        std::fflush(stdout);
        std::exit(77);
    };
    if (!LAB_HAVE_WINDOW)
        skip(
            "this build has no 'lab run' (libglfw3-dev or libimgui-dev was missing at configure "
            "time)");
    if (fw::test::run_command("command -v xvfb-run && command -v Xvfb && command -v xauth")
            .exit_code != 0)
        skip("xvfb-run not found (apt-get install xvfb xauth)");
}

// `lab run ARGS` on a fresh virtual display (-a: a free display number, so
// tests may run in parallel), in directory `dir` (F12 saves there). The server
// listens only on its socket file under /tmp (-nolisten local: no abstract
// socket, which every chroot and container on the machine would share), so a
// suite in a chroot (scripts/fresh-debian.sh) never meets the host's displays.
// -noreset: lab run's software fallback closes its only connection and opens
// another, and an X server that resets then (Xvfb's default) refuses it for
// a moment (lab run also retries for two seconds).
fw::test::CommandResult run_in_xvfb(const std::string& args, const std::string& dir = ".",
                                    const std::string& env = "") {
    return run("cd " + dir + " && " + env +
               " xvfb-run -a -s '-screen 0 1024x768x24 -nolisten local -noreset' " + lab() +
               " run " + args);
}

// `lab render ARGS -o FILE` on the default backend, as the grader renders.
void render_offscreen(const std::string& args, const std::string& file) {
    REQUIRE(run(lab() + " render " + args + " -o " + file).exit_code == 0);
}

fw::CompareResult compare_files(const std::string& actual, const std::string& expected) {
    fw::CompareResult r = fw::compare_images(fw::read_png(actual), fw::read_png(expected));
    MESSAGE(actual << " vs " << expected << ": " << r.summary());
    return r;
}

// The window's last frame (--screenshot) and the offscreen render of `args`;
// `env` is set for `lab run`, and `output` gets what it printed.
fw::CompareResult window_vs_offscreen(const std::string& args, const std::string& window_flags,
                                      const std::string& env = "", std::string* output = nullptr) {
    std::string dir = fw::test::out_dir();
    fw::test::CommandResult win = run_in_xvfb(
        args + " --frames 3 " + window_flags + " --screenshot " + dir + "/win.png", ".", env);
    REQUIRE(win.exit_code == 0);
    if (output) *output = win.output;
    render_offscreen(args, dir + "/off.png");
    return compare_files(dir + "/win.png", dir + "/off.png");
}

// How many pixels of column x = 12, inside the panel's left edge, differ
// between the window's frame and the offscreen one: the panel's height.
int panel_height(const std::string& window_png, const std::string& offscreen_png) {
    fw::Image win = fw::read_png(window_png), off = fw::read_png(offscreen_png);
    REQUIRE(win.width == off.width);
    REQUIRE(win.height == off.height);
    int rows = 0;
    for (int y = 0; y < win.height; ++y) {
        const fw::Rgba8 a = win.at(12, y), b = off.at(12, y);
        if (a.r != b.r || a.g != b.g || a.b != b.b) ++rows;
    }
    MESSAGE(window_png << ": the panel is " << rows << " pixels high");
    return rows;
}

}  // namespace

TEST_CASE("lab run without a display names DISPLAY and suggests xvfb-run, exit 3") {
    require_window_support();
    auto r = run("env -u DISPLAY -u WAYLAND_DISPLAY " + lab() + " run pipeline --frames 1");
    CHECK(r.exit_code == 3);
    CHECK(contains(r.output, "$DISPLAY is not set"));
    CHECK(contains(r.output, "WAYLAND_DISPLAY"));
    CHECK(contains(r.output, "xvfb-run -a lab run pipeline"));
    CHECK(contains(r.output, "lab render pipeline"));
    CHECK(contains(r.output, "lab serve pipeline"));
}

TEST_CASE("lab run --no-ui shows what lab render draws offscreen") {
    require_window_support();
    std::string output;
    fw::CompareResult r = window_vs_offscreen("pipeline", "--no-ui", "", &output);
    CHECK(r.passed);
    // A driver with GL 4.3 core is used as it is.
    CHECK_FALSE(contains(output, "Software rendering"));
}

TEST_CASE("lab run --set and --size reach the window") {
    require_window_support();
    fw::CompareResult r = window_vs_offscreen(
        "pipeline --set depth_test=false --set first=blue --size 320x240", "--no-ui");
    CHECK(r.actual_width == 320);
    CHECK(r.actual_height == 240);
    CHECK(r.passed);
}

TEST_CASE("lab run draws the parameter panel over the frame") {
    require_window_support();
    fw::CompareResult r = window_vs_offscreen("pipeline", "");
    CHECK_FALSE(r.size_mismatch);
    // The panel covers far more than the 0.1% the image check tolerates.
    CHECK(r.failed_fraction > 0.02);
}

TEST_CASE("keys change parameters and F12 saves what the window shows") {
    require_window_support();
    std::string dir = fw::test::out_dir();
    std::filesystem::remove(dir + "/screenshot-pipeline-001.png");
    // D turns the depth test off in frame 1, so the blue quad (drawn first)
    // no longer hides the red one; F12 in frame 2.
    auto r = run_in_xvfb("pipeline --set first=blue --frames 3 --no-ui --screenshot win.png", dir,
                         "LAB_RUN_SCRIPT=1:D,2:F12");
    REQUIRE(r.exit_code == 0);
    CHECK(contains(r.output, "screenshot-pipeline-001.png"));
    REQUIRE(std::filesystem::exists(dir + "/screenshot-pipeline-001.png"));

    render_offscreen("pipeline --set first=blue --set depth_test=false", dir + "/off.png");
    CHECK(compare_files(dir + "/win.png", dir + "/off.png").passed);
    CHECK(compare_files(dir + "/screenshot-pipeline-001.png", dir + "/off.png").passed);
    render_offscreen("pipeline --set first=blue", dir + "/depth_on.png");
    CHECK_FALSE(compare_files(dir + "/win.png", dir + "/depth_on.png").passed);
}

TEST_CASE("a malformed LAB_RUN_SCRIPT is a usage error naming the variable") {
    require_window_support();
    auto r = run_in_xvfb("pipeline --frames 1", ".", "LAB_RUN_SCRIPT=x:D");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "LAB_RUN_SCRIPT: 'x:D' is not FRAME:KEY"));
}

TEST_CASE("lab run on a driver without GL 4.3 renders in software, says so once, same frame") {
    require_window_support();
    std::string output;
    fw::CompareResult r = window_vs_offscreen("pipeline", "--no-ui", kOldDriver, &output);
    CHECK(r.passed);
    CHECK(occurrences(output, kSoftwareLine) == 1);
    CHECK(contains(output, "$MESA_GL_VERSION_OVERRIDE was '4.1'"));
}

TEST_CASE("the panel shows the software rendering line") {
    require_window_support();
    std::string dir = fw::test::out_dir();
    render_offscreen("pipeline", dir + "/off.png");
    REQUIRE(run_in_xvfb("pipeline --frames 3 --screenshot " + dir + "/gpu.png").exit_code == 0);
    REQUIRE(
        run_in_xvfb("pipeline --frames 3 --screenshot " + dir + "/software.png", ".", kOldDriver)
            .exit_code == 0);
    const int gpu = panel_height(dir + "/gpu.png", dir + "/off.png");
    const int software = panel_height(dir + "/software.png", dir + "/off.png");
    CHECK(gpu > 100);
    // The line wraps into several lines of 13-pixel text above the widgets.
    CHECK(software >= gpu + 3 * 13);
}

TEST_CASE("without GL 4.3 core in software either, lab run names the version and lab serve") {
    require_window_support();
    // Mesa derives its version from its extensions, for llvmpipe too: without
    // compute shaders every attempt gets GL 4.2.
    auto r =
        run_in_xvfb("pipeline --frames 1", ".", "MESA_EXTENSION_OVERRIDE=-GL_ARB_compute_shader");
    CHECK(r.exit_code == 3);
    fw::test::check_mentions(
        r.output,
        {"needs OpenGL 4.3 core", "the GPU driver offers only OpenGL 4.2",
         "software renderer (llvmpipe) offers only OpenGL 4.2",
         "'lab serve pipeline', then open the URL it prints", "'lab render pipeline -o out.png'"});
    CHECK_FALSE(contains(r.output, "Software rendering"));
}

TEST_CASE("when software rendering was already forced, lab run fails without trying it again") {
    require_window_support();
    auto r = run_in_xvfb("pipeline --frames 1", ".", "LIBGL_ALWAYS_SOFTWARE=1 " + kOldDriver);
    CHECK(r.exit_code == 3);
    fw::test::check_mentions(r.output, {"needs OpenGL 4.3 core", "offers only OpenGL 4.1",
                                        "$LIBGL_ALWAYS_SOFTWARE is '1'", "'lab serve pipeline'",
                                        "'lab render pipeline -o out.png'"});
    CHECK_FALSE(contains(r.output, "Software rendering"));
}
