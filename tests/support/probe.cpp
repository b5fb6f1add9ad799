#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "framework/text.hpp"
#include "test_support.hpp"

namespace fw::test {

std::string bin_dir() { return LAB_BIN_DIR; }
std::string source_dir() { return LAB_SOURCE_DIR; }

std::string out_dir() {
    const doctest::detail::TestCase* tc = doctest::getContextOptions()->currentTest;
    std::string name = tc ? tc->m_name : "unnamed";
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    // A test that runs once per backend (serve.osmesa and serve.egl run side
    // by side) writes under its backend's name, so the runs never share a file.
    std::filesystem::path dir = std::filesystem::path(LAB_TEST_OUT_DIR);
    if (const char* backend = std::getenv("LAB_BACKEND"); backend && *backend) dir /= backend;
    dir /= name;
    std::filesystem::create_directories(dir);
    return dir.string();
}

namespace {
std::vector<std::string>& marked() {
    static std::vector<std::string> paths;
    return paths;
}

std::uintmax_t bytes_under(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_directory(path, ec)) {
        const std::uintmax_t size = std::filesystem::file_size(path, ec);
        return ec ? 0 : size;
    }
    std::uintmax_t sum = 0;
    for (auto it = std::filesystem::recursive_directory_iterator(
             path, std::filesystem::directory_options::skip_permission_denied, ec);
         !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
        if (it->is_regular_file(ec) && !it->is_symlink(ec)) sum += it->file_size(ec);
    return sum;
}
}  // namespace

void remove_when_passed(const std::string& path) {
    if (std::find(marked().begin(), marked().end(), path) == marked().end())
        marked().push_back(path);
}

void remove_marked(bool passed) {
    const char* keep = std::getenv("LAB_KEEP_TEST_OUT");
    if (marked().empty()) return;
    if (!passed || (keep && std::string(keep) == "1")) {
        std::printf("kept for a look: %s\n", join(marked(), ", ").c_str());
        return;
    }
    std::uintmax_t freed = 0;
    for (const std::string& path : marked()) {
        freed += bytes_under(path);
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
        if (ec) std::printf("could not remove %s: %s\n", path.c_str(), ec.message().c_str());
    }
    std::printf("removed after passing: %s (%.0f MB)\n", join(marked(), ", ").c_str(),
                static_cast<double>(freed) / 1e6);
}

bool probe_rgb(const Image& img, int x, int y, glm::vec3 expected, float tol) {
    if (x < 0 || y < 0 || x >= img.width || y >= img.height) {
        MESSAGE("probe (" << x << ", " << y << ") is outside the " << img.width << "x" << img.height
                          << " image");
        return false;
    }
    Rgba8 p = img.at(x, y);
    glm::vec3 observed(p.r / 255.0f, p.g / 255.0f, p.b / 255.0f);
    glm::vec3 diff = glm::abs(observed - expected);
    bool pass = diff.r <= tol && diff.g <= tol && diff.b <= tol;
    char line[256];
    std::snprintf(line, sizeof line,
                  "probe (%d, %d): expected (%.4f, %.4f, %.4f) observed (%.4f, %.4f, %.4f) "
                  "tolerance %.4f: %s",
                  x, y, expected.r, expected.g, expected.b, observed.r, observed.g, observed.b, tol,
                  pass ? "pass" : "FAIL");
    MESSAGE(line);
    return pass;
}

bool probe_depth(const DepthImage& img, int x, int y, float expected, float tol) {
    if (x < 0 || y < 0 || x >= img.width || y >= img.height) {
        MESSAGE("depth probe (" << x << ", " << y << ") is outside the image");
        return false;
    }
    float observed = img.at(x, y);
    bool pass = std::fabs(observed - expected) <= tol;
    char line[200];
    std::snprintf(line, sizeof line,
                  "depth probe (%d, %d): expected %.7f observed %.7f tolerance %.1e: %s", x, y,
                  expected, observed, tol, pass ? "pass" : "FAIL");
    MESSAGE(line);
    return pass;
}

void check_mentions(const std::string& message, const std::vector<std::string>& needles) {
    MESSAGE("observed message:\n" << message);
    for (const std::string& n : needles)
        CHECK_MESSAGE(message.find(n) != std::string::npos,
                      "expected the message to contain '" << n << "'");
}

LabUnderTest::LabUnderTest(const RegisteredLab& lab_) : lab(lab_), renderer(lab, context_info()) {}
LabUnderTest::LabUnderTest(const std::string& id) : LabUnderTest(find_lab(id)) {}

ParamValues LabUnderTest::params(const Settings& settings) const {
    ParamValues p = default_params(lab);
    for (const auto& [name, value] : settings) p.set(name, value);
    return p;
}

RenderOutput LabUnderTest::render(const Settings& settings, int width, int height) {
    return renderer.render(params(settings), width, height);
}

glm::vec3 rgb_at(const Image& img, int x, int y) {
    const Rgba8 p = img.at(x, y);
    return glm::vec3(p.r, p.g, p.b) / 255.0f;
}

bool near(glm::vec3 a, glm::vec3 b, float tol) {
    return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::vec3(tol)));
}

void for_each_checkpoint(const RegisteredLab& lab, LabRenderer& renderer, size_t min_count,
                         const CheckpointVisitor& visit) {
    const std::vector<Checkpoint> checkpoints = load_checkpoints(lab);
    CHECK(checkpoints.size() >= min_count);
    size_t hidden = 0;
    for (const Checkpoint& cp : checkpoints) {
        CAPTURE(cp.name);
        hidden += cp.visibility == "hidden";
        const ParamValues params = checkpoint_params(lab, cp);
        visit(cp, params, renderer.render(params, 512, 512));
    }
    CHECK(hidden > 0);
    CHECK(hidden < checkpoints.size());
}

void check_probes_and_stats(const nlohmann::json& checks, const RenderOutput& out) {
    for (const nlohmann::json& check : checks) {
        CAPTURE(check.dump());
        if (check["kind"] == "probe") {
            const int x = check["at"][0].get<int>(), y = check["at"][1].get<int>();
            if (check.contains("depth")) {
                CHECK(probe_depth(out.depth, x, y, check["depth"].get<float>(),
                                  check.value("tolerance", 1e-5f)));
            } else {
                const nlohmann::json& c = check["color"];
                CHECK(probe_rgb(out.color, x, y,
                                {c[0].get<float>(), c[1].get<float>(), c[2].get<float>()},
                                check.value("tolerance", 0.01f)));
            }
        } else if (check["kind"] == "stat") {
            // "a.b" names stats["a"]["b"].
            std::string path = check["stat"];
            const nlohmann::json* value = &out.stats;
            for (size_t dot; (dot = path.find('.')) != std::string::npos; path.erase(0, dot + 1))
                value = &value->at(path.substr(0, dot));
            CHECK(value->at(path) == check["equals"]);
        }
    }
}

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void write_text(const std::string& path, const std::string& text) {
    const std::filesystem::path p(path);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    std::ofstream out(path, std::ios::binary);
    out << text;
    REQUIRE_MESSAGE(out.flush(), "cannot write " << path);
}

CommandResult run_command(const std::string& command) {
    CommandResult r;
    std::string full = command + " 2>&1";
    FILE* p = popen(full.c_str(), "r");
    if (!p) return r;
    std::array<char, 4096> buf;
    size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.output.append(buf.data(), n);
    int status = pclose(p);
    if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
    return r;
}

}  // namespace fw::test
