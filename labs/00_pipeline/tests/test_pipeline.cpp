// Lab 0 `pipeline`. Every expectation is computed here from the sheet's
// numbers (docs/labs.md, labs/00_pipeline/README.md), never read from a reference
// image or from the lab's own code.
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "framework/checkpoints.hpp"
#include "framework/lab.hpp"
#include "framework/render.hpp"
#include "tests/support/test_support.hpp"

namespace {

constexpr int kSize = 512;
const glm::vec3 kBlack{0, 0, 0}, kRed{1, 0, 0}, kGreen{0, 1, 0}, kBlue{0, 0, 1};
const glm::vec3 kYellow{1, 1, 0}, kCyan{0, 1, 1}, kMagenta{1, 0, 1};

// NDC -> the window pixel whose square contains that point: (ndc + 1) / 2 * W.
int pixel(float ndc) { return static_cast<int>(std::floor((ndc + 1.0f) * 0.5f * kSize)); }

using fw::test::Settings;

struct Pipeline : fw::test::LabUnderTest {
    Pipeline() : LabUnderTest() {}
};

long differing_pixels(const fw::Image& a, const fw::Image& b) {
    REQUIRE(a.pixels.size() == b.pixels.size());
    long n = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) n += a.pixels[i] != b.pixels[i];
    return n;
}

// Pixels that differ between a and b and have no background (black) pixel
// of `a` among their 8 neighbours.
long differing_off_outline(const fw::Image& a, const fw::Image& b) {
    REQUIRE(a.pixels.size() == b.pixels.size());
    const fw::Rgba8 black{0, 0, 0, 255};
    long n = 0;
    for (int y = 1; y + 1 < a.height; ++y)
        for (int x = 1; x + 1 < a.width; ++x) {
            if (a.at(x, y) == b.at(x, y)) continue;
            bool outline = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) outline |= a.at(x + dx, y + dy) == black;
            if (!outline) {
                MESSAGE("pixel (" << x << ", " << y << ") differs inside the outline");
                ++n;
            }
        }
    return n;
}

// The sheet's face set: 6 vertices (NDC) with one colour each, 4 triangles.
const glm::vec2 kFacePositions[6] = {{-0.8f, 0.5f}, {-0.5f, -0.3f}, {0.0f, 0.5f},
                                     {0.0f, -0.8f}, {0.5f, -0.3f},  {0.8f, 0.5f}};
const glm::vec3 kFaceColors[6] = {kRed, kGreen, kBlue, kYellow, kCyan, kMagenta};
const int kFaceIndices[4][3] = {{0, 2, 1}, {1, 3, 4}, {1, 4, 2}, {2, 4, 5}};

glm::vec2 to_window(glm::vec2 ndc) { return (ndc + 1.0f) * 0.5f * float(kSize); }

// Probes the pixel holding triangle t's centroid for the vertex colours
// interpolated with the barycentric coordinates of that pixel's centre.
bool probe_face_centroid(const fw::Image& img, int t) {
    const glm::vec2 a = to_window(kFacePositions[kFaceIndices[t][0]]);
    const glm::vec2 b = to_window(kFacePositions[kFaceIndices[t][1]]);
    const glm::vec2 c = to_window(kFacePositions[kFaceIndices[t][2]]);
    const glm::vec2 centroid = (a + b + c) / 3.0f;
    const int x = int(centroid.x), y = int(centroid.y);
    const glm::vec2 p(x + 0.5f, y + 0.5f);
    auto cross = [](glm::vec2 u, glm::vec2 v) { return u.x * v.y - u.y * v.x; };
    const float area = cross(b - a, c - a);
    const float wa = cross(b - p, c - p) / area, wb = cross(c - p, a - p) / area;
    const glm::vec3 expected = wa * kFaceColors[kFaceIndices[t][0]] +
                               wb * kFaceColors[kFaceIndices[t][1]] +
                               (1.0f - wa - wb) * kFaceColors[kFaceIndices[t][2]];
    return fw::test::probe_rgb(img, x, y, expected, 2.0f / 255.0f);
}

// The sheet's cube: [-0.5, 0.5]^3, faces +x red, -x cyan, +y green,
// -y magenta, +z blue, -z yellow; M = rotateX(pitch) * rotateY(yaw),
// eye (0, 0, 3) looking at the origin, 45 degree vertical field of view.
struct CubeFace {
    glm::vec3 normal, color;
};
const CubeFace kCubeFaces[6] = {{{1, 0, 0}, kRed},      {{-1, 0, 0}, kCyan}, {{0, 1, 0}, kGreen},
                                {{0, -1, 0}, kMagenta}, {{0, 0, 1}, kBlue},  {{0, 0, -1}, kYellow}};
const glm::vec3 kEye{0, 0, 3};

struct ProjectedFace {
    glm::ivec2 centre;  // pixel holding the projected face centre
    bool faces_eye;     // a front face: its outside is turned towards the eye
    glm::vec3 color;
};

std::vector<ProjectedFace> project_cube(float yaw, float pitch) {
    const glm::mat4 model = glm::rotate(glm::mat4(1), glm::radians(pitch), {1, 0, 0}) *
                            glm::rotate(glm::mat4(1), glm::radians(yaw), {0, 1, 0});
    const glm::mat4 clip = glm::perspective(glm::radians(45.0f), 1.0f, 0.1f, 100.0f) *
                           glm::lookAt(kEye, glm::vec3(0), {0, 1, 0}) * model;
    std::vector<ProjectedFace> out;
    for (const CubeFace& f : kCubeFaces) {
        const glm::vec4 c = clip * glm::vec4(0.5f * f.normal, 1.0f);
        const glm::vec3 centre = glm::vec3(model * glm::vec4(0.5f * f.normal, 1.0f));
        const glm::vec3 normal = glm::vec3(model * glm::vec4(f.normal, 0.0f));
        out.push_back({{pixel(c.x / c.w), pixel(c.y / c.w)},
                       glm::dot(normal, kEye - centre) > 0.0f,
                       f.color});
    }
    return out;
}

}  // namespace

TEST_CASE("pipeline: the declaration has the sheet's parameters and defaults") {
    const fw::RegisteredLab& lab = fw::test::this_lab();
    const fw::ParamValues p = fw::default_params(lab);
    CHECK(p.text("scene") == "order");
    CHECK(p.flag("depth_test"));
    CHECK(p.text("first") == "red");
    CHECK(p.text("storage") == "indexed");
    CHECK(p.text("primitive") == "triangles");
    CHECK(p.text("cull") == "back");
    for (const fw::Param& param : lab.info.params) {
        INFO("parameter " << param.name);
        CHECK(!param.help_text.empty());
        CHECK(param.shortcut != 0);
    }
}

TEST_CASE("pipeline: order: the overlap shows the depth test or else the last quad drawn") {
    Pipeline lab;
    // Red [-0.6, 0.2]^2 at z 0.5, blue [-0.2, 0.6]^2 at z -0.5 (nearer).
    const int red_only = pixel(-0.4f), blue_only = pixel(0.4f), overlap = pixel(0.0f);
    for (const char* depth : {"true", "false"}) {
        for (const char* first : {"red", "blue"}) {
            CAPTURE(depth);
            CAPTURE(first);
            fw::RenderOutput out =
                lab.render({{"scene", "order"}, {"depth_test", depth}, {"first", first}});
            const bool depth_on = std::string(depth) == "true";
            const glm::vec3 top = depth_on || std::string(first) == "red" ? kBlue : kRed;
            CHECK(fw::test::probe_rgb(out.color, overlap, overlap, top));
            CHECK(fw::test::probe_rgb(out.color, pixel(-0.15f), pixel(0.15f), top));
            CHECK(fw::test::probe_rgb(out.color, red_only, red_only, kRed));
            CHECK(fw::test::probe_rgb(out.color, blue_only, blue_only, kBlue));
            CHECK(fw::test::probe_rgb(out.color, pixel(-0.8f), pixel(0.8f), kBlack));
            CHECK(fw::test::probe_rgb(out.color, pixel(0.8f), pixel(-0.8f), kBlack));
            // Edges: red's left edge is at window x 102.4, blue's top at 409.6.
            CHECK(fw::test::probe_rgb(out.color, 102, red_only, kRed));
            CHECK(fw::test::probe_rgb(out.color, 101, red_only, kBlack));
            CHECK(fw::test::probe_rgb(out.color, blue_only, 409, kBlue));
            CHECK(fw::test::probe_rgb(out.color, blue_only, 410, kBlack));
        }
    }
}

TEST_CASE("pipeline: order: the depth buffer holds each quad's window depth (z + 1) / 2") {
    Pipeline lab;
    for (const char* first : {"red", "blue"}) {
        CAPTURE(first);
        fw::RenderOutput out = lab.render({{"scene", "order"}, {"first", first}});
        CHECK(fw::test::probe_depth(out.depth, pixel(-0.4f), pixel(-0.4f), 0.75f, 1e-6f));
        CHECK(fw::test::probe_depth(out.depth, pixel(0.4f), pixel(0.4f), 0.25f, 1e-6f));
        CHECK(fw::test::probe_depth(out.depth, pixel(0.0f), pixel(0.0f), 0.25f, 1e-6f));
        CHECK(fw::test::probe_depth(out.depth, pixel(-0.8f), pixel(0.8f), 1.0f, 1e-6f));
    }
}

TEST_CASE("pipeline: indexed: indexed and flat storage draw identical images") {
    Pipeline lab;
    fw::RenderOutput indexed = lab.render({{"scene", "indexed"}, {"storage", "indexed"}});
    fw::RenderOutput flat = lab.render({{"scene", "indexed"}, {"storage", "flat"}});
    for (int t = 0; t < 4; ++t) {
        CAPTURE(t);
        CHECK(probe_face_centroid(indexed.color, t));
        CHECK(probe_face_centroid(flat.color, t));
    }
    CHECK(fw::test::probe_rgb(indexed.color, pixel(-0.8f), pixel(-0.8f), kBlack));
    CHECK(differing_pixels(indexed.color, flat.color) == 0);
    CHECK(indexed.stats["primitives_generated"] == 4);
    CHECK(flat.stats["primitives_generated"] == 4);
}

TEST_CASE("pipeline: lab_stats report the vertex layout as GL holds it, in every scene") {
    Pipeline lab;
    for (const char* scene : {"order", "indexed", "primitives", "culling"}) {
        CAPTURE(scene);
        const nlohmann::json layout = lab.render({{"scene", scene}}).stats["lab_stats"]["layout"];
        INFO(layout.dump());
        // Two vec3 a vertex, 24 bytes: the position at 0, the colour at 12.
        CHECK(layout["position"] ==
              nlohmann::json{{"enabled", 1}, {"size", 3}, {"stride", 24}, {"offset", 0}});
        CHECK(layout["color"] ==
              nlohmann::json{{"enabled", 1}, {"size", 3}, {"stride", 24}, {"offset", 12}});
    }
}

TEST_CASE("pipeline: indexed: lab_stats report the bytes each storage holds") {
    Pipeline lab;
    // A vertex is two vec3 (24 bytes), an index one GLuint (4 bytes).
    const int vertex = 2 * 3 * 4, index = 4;
    const nlohmann::json indexed =
        lab.render({{"scene", "indexed"}, {"storage", "indexed"}}).stats["lab_stats"];
    const nlohmann::json flat =
        lab.render({{"scene", "indexed"}, {"storage", "flat"}}).stats["lab_stats"];
    INFO("indexed: " << indexed.dump());
    INFO("flat: " << flat.dump());
    CHECK(indexed["storage"] == "indexed");
    CHECK(indexed["vertex_bytes"] == 6 * vertex);
    CHECK(indexed["index_bytes"] == 12 * index);
    CHECK(indexed["total_bytes"] == 6 * vertex + 12 * index);
    CHECK(flat["storage"] == "flat");
    CHECK(flat["vertex_bytes"] == 12 * vertex);
    CHECK(flat["index_bytes"] == 0);
    CHECK(flat["total_bytes"] == 12 * vertex);
    CHECK(flat["total_bytes"] > indexed["total_bytes"]);
    CHECK(indexed["flat"] == flat["flat"]);
    CHECK(indexed["indexed"] == flat["indexed"]);
}

TEST_CASE("pipeline: primitives: 6 vertices make the number of primitives GL's rules give") {
    Pipeline lab;
    const std::pair<const char*, int> modes[] = {
        {"points", 6},    {"lines", 3},          {"line_strip", 5},  {"line_loop", 6},
        {"triangles", 2}, {"triangle_strip", 4}, {"triangle_fan", 4}};
    std::vector<fw::Image> images;
    for (const auto& [mode, count] : modes) {
        CAPTURE(mode);
        fw::RenderOutput out = lab.render({{"scene", "primitives"}, {"primitive", mode}});
        CHECK(out.stats["primitives_generated"] == count);
        images.push_back(out.color);
    }
    // Each mode draws its own picture.
    for (size_t i = 0; i < images.size(); ++i)
        for (size_t j = i + 1; j < images.size(); ++j) {
            CAPTURE(modes[i].first);
            CAPTURE(modes[j].first);
            CHECK(differing_pixels(images[i], images[j]) > 0);
        }
    // Points: an 8 px square in its colour at every vertex, black between.
    for (int v = 0; v < 6; ++v) {
        CAPTURE(v);
        const glm::vec2 w = to_window(kFacePositions[v]);
        CHECK(fw::test::probe_rgb(images[0], int(w.x), int(w.y), kFaceColors[v]));
        CHECK(fw::test::probe_rgb(images[0], int(w.x) + 6, int(w.y) + 6, kBlack));
    }
    // Triangles (0,1,2) and (3,4,5): the centroid of (0,1,2), red, green and
    // blue in equal parts, is filled.
    const glm::vec2 c012 =
        to_window((kFacePositions[0] + kFacePositions[1] + kFacePositions[2]) / 3.0f);
    CHECK(fw::test::probe_rgb(images[0], int(c012.x), int(c012.y), kBlack));
    CHECK(fw::test::probe_rgb(images[4], int(c012.x), int(c012.y), glm::vec3(1.0f / 3.0f), 0.02f));
}

TEST_CASE("pipeline: culling: back shows the front faces, front the insides of the back faces") {
    Pipeline lab;
    const float yaw = 30, pitch = 20;
    auto render = [&](const char* cull, const char* depth = "true") {
        return lab.render({{"scene", "culling"},
                           {"cull", cull},
                           {"depth_test", depth},
                           {"yaw", std::to_string(yaw)},
                           {"pitch", std::to_string(pitch)}});
    };
    fw::RenderOutput back = render("back"), front = render("front"), none = render("none");
    const int centre = kSize / 2;
    // The ray through the centre enters the cube through +z and leaves through -z.
    CHECK(fw::test::probe_rgb(back.color, centre, centre, kBlue));
    CHECK(fw::test::probe_rgb(front.color, centre, centre, kYellow));
    for (const ProjectedFace& f : project_cube(yaw, pitch)) {
        CAPTURE(f.centre.x);
        CAPTURE(f.centre.y);
        CAPTURE(f.faces_eye);
        const fw::Image& seen = f.faces_eye ? back.color : front.color;
        CHECK(fw::test::probe_rgb(seen, f.centre.x, f.centre.y, f.color));
    }
    CHECK(fw::test::probe_rgb(back.color, 20, 20, kBlack));
    CHECK(differing_pixels(back.color, front.color) > 10000);
    // A closed convex object: with the depth test, culling back faces changes
    // nothing, except on the outline, where a front and a back face meet at
    // the same depth and rounding may let either win. Without the depth test,
    // culling alone still draws the cube right.
    CHECK(differing_off_outline(back.color, none.color) == 0);
    CHECK(differing_pixels(back.color, none.color) <= 20);
    CHECK(differing_pixels(back.color, render("back", "false").color) == 0);
    // GL counts primitives before culling.
    for (const fw::RenderOutput* out : {&back, &front, &none})
        CHECK(out->stats.at("primitives_generated") == 12);
}

TEST_CASE("pipeline: culling: the face centres agree with the sheet in another orientation") {
    Pipeline lab;
    const float yaw = -120, pitch = -35;
    fw::RenderOutput back = lab.render({{"scene", "culling"},
                                        {"cull", "back"},
                                        {"yaw", std::to_string(yaw)},
                                        {"pitch", std::to_string(pitch)}});
    int visible = 0;
    for (const ProjectedFace& f : project_cube(yaw, pitch)) {
        if (!f.faces_eye) continue;
        ++visible;
        CAPTURE(f.centre.x);
        CAPTURE(f.centre.y);
        CHECK(fw::test::probe_rgb(back.color, f.centre.x, f.centre.y, f.color));
    }
    CHECK(visible == 3);
}

TEST_CASE("pipeline: checkpoints.json: its probes and stats hold for the solution") {
    Pipeline lab;
    std::vector<std::string> scenes;
    fw::test::for_each_checkpoint(
        lab.lab, lab.renderer, 6,
        [&](const fw::Checkpoint& cp, const fw::ParamValues& params, const fw::RenderOutput& out) {
            scenes.push_back(params.text("scene"));
            fw::test::check_probes_and_stats(cp.checks, out);
        });
    for (const char* scene : {"order", "indexed", "primitives", "culling"})
        CHECK(std::count(scenes.begin(), scenes.end(), scene) >= 2);
}
