// The `lab` executable's errors (docs/contract.md, Exit status and errors):
// every error names the thing at fault and what would fix it, and exits
// non-zero. Each case runs the real
// executable as a child process and checks the exit status and the message.
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/test_support.hpp"

namespace {

std::string lab() { return fw::test::bin_dir() + "/lab"; }

fw::test::CommandResult run_lab(const std::string& args, const std::string& env = "") {
    std::string cmd = (env.empty() ? "" : "env " + env + " ") + lab() + " " + args;
    fw::test::CommandResult r = fw::test::run_command(cmd);
    MESSAGE("$ " << cmd << "\nexit " << r.exit_code << "\n" << r.output);
    return r;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("lab list names lab 0 and exits 0") {
    auto r = run_lab("list");
    CHECK(r.exit_code == 0);
    CHECK(contains(r.output, "pipeline"));
    auto j = run_lab("list --json");
    CHECK(j.exit_code == 0);
    CHECK(contains(j.output, "\"depth_test\""));
}

TEST_CASE("unknown lab lists the labs, exit 2") {
    auto r = run_lab("render no_such_lab -o /dev/null");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "unknown lab 'no_such_lab'"));
    CHECK(contains(r.output, "pipeline"));
}

TEST_CASE("unknown parameter lists the parameters, exit 2") {
    auto r = run_lab("render pipeline --set bogus=1 -o /dev/null");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "no parameter 'bogus'"));
    CHECK(contains(r.output, "depth_test"));
    CHECK(contains(r.output, "scene"));
}

TEST_CASE("unknown enum value lists the valid values, exit 2") {
    auto r = run_lab("render pipeline --set scene=teapot -o /dev/null");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "unknown value 'teapot'"));
    CHECK(contains(r.output, "order, indexed, primitives, culling"));
}

TEST_CASE("a value out of range or not a number gives the range, exit 2") {
    auto out_of_range = run_lab("render pipeline --set yaw=1000 -o /dev/null");
    CHECK(out_of_range.exit_code == 2);
    CHECK(contains(out_of_range.output, "out of range"));
    CHECK(contains(out_of_range.output, "[-180, 180]"));
    auto nan = run_lab("render pipeline --set yaw=abc -o /dev/null");
    CHECK(nan.exit_code == 2);
    CHECK(contains(nan.output, "'abc' is not a number"));
    CHECK(contains(nan.output, "[-180, 180]"));
    auto bad_bool = run_lab("render pipeline --set depth_test=maybe -o /dev/null");
    CHECK(bad_bool.exit_code == 2);
    CHECK(contains(bad_bool.output, "true or false"));
    auto no_equals = run_lab("render pipeline --set depth_test -o /dev/null");
    CHECK(no_equals.exit_code == 2);
    CHECK(contains(no_equals.output, "name=value"));
}

TEST_CASE("unknown checkpoint lists the checkpoints, exit 2") {
    auto r = run_lab("render pipeline --checkpoint nope -o /dev/null");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "no checkpoint 'nope'"));
    auto list = run_lab("checkpoints pipeline --json");
    REQUIRE(list.exit_code == 0);
    // The first listed checkpoint name must appear in the error's list.
    auto pos = list.output.find("\"name\": \"");
    REQUIRE(pos != std::string::npos);
    std::string first = list.output.substr(pos + 9, list.output.find('"', pos + 9) - pos - 9);
    CHECK(contains(r.output, first));
}

TEST_CASE("sizes of zero, malformed, or above the GL limit are refused, exit 2") {
    auto zero = run_lab("render pipeline --size 0x512 -o /dev/null");
    CHECK(zero.exit_code == 2);
    CHECK(contains(zero.output, "--size '0x512'"));
    auto malformed = run_lab("render pipeline --size 512 -o /dev/null");
    CHECK(malformed.exit_code == 2);
    CHECK(contains(malformed.output, "WxH"));
    auto huge = run_lab("render pipeline --size 60000x4 -o /dev/null");
    CHECK(huge.exit_code == 2);
    CHECK(contains(huge.output, "60000"));
    CHECK(contains(huge.output, "GL_MAX_"));
}

TEST_CASE("unknown backend, on the command line and in LAB_BACKEND, exit 2") {
    auto r = run_lab("render pipeline --backend vulkan -o /dev/null");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "vulkan"));
    if (fw::backend_compiled_in(fw::Backend::OSMesa)) {
        CHECK(contains(r.output, "auto, osmesa, egl"));
    } else {
        CHECK(contains(r.output, "auto, egl (this build has no osmesa)"));
    }
    auto e = run_lab("render pipeline -o /dev/null", "LAB_BACKEND=vulkan");
    CHECK(e.exit_code == 2);
    CHECK(contains(e.output, "LAB_BACKEND"));
}

TEST_CASE(
    "an EGL with no vendor library says what is missing and what else this build offers, exit 3") {
    const std::string no_vendor = "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json";
    auto r = run_lab("render pipeline --backend egl -o /dev/null", no_vendor);
    CHECK(r.exit_code == 3);
    CHECK(contains(r.output, "egl"));
    // --backend osmesa is offered exactly when this build has it.
    CHECK(contains(r.output, "--backend osmesa") == fw::backend_compiled_in(fw::Backend::OSMesa));

    auto a = run_lab("render pipeline --backend auto -o /dev/null", no_vendor);
    INFO("auto: " << a.output);
    if (fw::backend_compiled_in(fw::Backend::OSMesa)) {
        CHECK(a.exit_code == 0);  // falls back to OSMesa
    } else {
        CHECK(a.exit_code == 3);
        CHECK(contains(a.output, "tried egl; this build has no osmesa"));
    }
}

TEST_CASE("a missing shader file names its path, exit 1") {
    std::string dir = fw::test::out_dir() + "/empty_shaders";
    std::filesystem::create_directories(dir);
    auto r = run_lab("render pipeline -o /dev/null", "LAB_SHADER_DIR=" + dir);
    CHECK(r.exit_code == 1);
    CHECK(contains(r.output, dir + "/00_pipeline/"));
}

TEST_CASE("a shader that fails to compile: path, stage, line and source line, exit 1") {
    namespace fs = std::filesystem;
    std::string dir = fw::test::out_dir() + "/broken_shaders";
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy(fw::test::source_dir() + "/shaders/00_pipeline", dir + "/00_pipeline");
    // Break the first fragment shader: an undeclared name on a line of its own.
    std::string broken;
    for (const auto& entry : fs::directory_iterator(dir + "/00_pipeline"))
        if (entry.path().extension() == ".frag") broken = entry.path().string();
    REQUIRE(!broken.empty());
    std::ifstream in(broken);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    int line = 1;
    for (char c : text.substr(0, text.find("void main"))) line += c == '\n';
    std::ofstream(broken) << text.substr(0, text.find("void main"))
                          << "float oops = undeclared_name;\n"
                          << text.substr(text.find("void main"));
    auto r = run_lab("render pipeline -o /dev/null", "LAB_SHADER_DIR=" + dir);
    CHECK(r.exit_code == 1);
    // The path may be shown relative to the working directory; file and line together.
    std::string file_line = "broken_shaders/00_pipeline/" + fs::path(broken).filename().string() +
                            ":" + std::to_string(line);
    CHECK(contains(r.output, file_line));
    CHECK(contains(r.output, "fragment"));
    CHECK(contains(r.output, "float oops = undeclared_name;"));
}

TEST_CASE("an output file that cannot be written names its path, exit 1") {
    auto r = run_lab("render pipeline -o /nonexistent-dir/out.png");
    CHECK(r.exit_code == 1);
    CHECK(contains(r.output, "/nonexistent-dir/out.png"));
}

TEST_CASE("render writes PNG, PFM and stats with every documented field") {
    std::string dir = fw::test::out_dir();
    auto r = run_lab("render pipeline -o " + dir + "/f.png --depth-out " + dir + "/f.pfm --stats " +
                     dir + "/f.json --size 64x32");
    REQUIRE(r.exit_code == 0);
    fw::Image img = fw::read_png(dir + "/f.png");
    CHECK(img.width == 64);
    CHECK(img.height == 32);
    fw::DepthImage depth = fw::read_pfm(dir + "/f.pfm");
    CHECK(depth.width == 64);
    CHECK(depth.height == 32);
    std::ifstream in(dir + "/f.json");
    auto stats = nlohmann::json::parse(in);
    for (const char* key : {"lab", "params", "backend", "gl_version", "gl_renderer", "width",
                            "height", "primitives_generated", "render_ms"})
        CHECK_MESSAGE(stats.contains(key), "stats lacks " << key);
    CHECK(stats["width"] == 64);
    CHECK(stats["params"]["scene"] == "order");
    CHECK(stats["params"].size() ==
          nlohmann::json::parse(run_lab("list --json").output)[0]["params"].size());
}

TEST_CASE("lab render: a square scene keeps its shape in a frame of another shape") {
    // Lab 1's world square [-2, 2]^2 fills the centred 600x600 of an 800x600
    // frame (x from 100): its body, [-0.5, 0.5]^2 at the identity, spans
    // pixels 325..475 both ways. Stretched to the frame it would span x
    // 300..500.
    const std::string png = fw::test::out_dir() + "/letterboxed.png";
    auto r = run_lab("render transforms --size 800x600 -o " + png);
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    const fw::Image img = fw::read_png(png);
    REQUIRE(img.width == 800);
    REQUIRE(img.height == 600);
    const glm::vec3 red{1, 0, 0}, black{0, 0, 0};
    CHECK(fw::test::probe_rgb(img, 327, 300, red));
    CHECK(fw::test::probe_rgb(img, 472, 300, red));
    CHECK(fw::test::probe_rgb(img, 400, 227, red));
    CHECK(fw::test::probe_rgb(img, 400, 372, red));
    CHECK(fw::test::probe_rgb(img, 322, 300, black));
    CHECK(fw::test::probe_rgb(img, 478, 300, black));
    CHECK(fw::test::probe_rgb(img, 305, 300, black));
}
