// Lab 8 `texture-mapping`: the declaration, the textures, the scene
// coordinates (the mappings, per vertex and per fragment, lit, the image
// file), the unit functions planar(), cylindrical() and spherical(), and the
// checkpoints. Every expectation is computed here from the sheet's numbers
// (labs/08_texture_mapping/README.md) with a ray cast of the unit sphere and
// GL's texture rules, never read from a reference image or the lab's code.
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"
#include "framework/gl/shader.hpp"
#include "mappings.hpp"
#include "texture_mapping_test.hpp"
#include "textures.hpp"

using namespace texture_mapping_test;
using texture_mapping::Wrap;

namespace {

constexpr double kPi = 3.14159265358979323846;

// --- the textures ----------------------------------------------------------

// The sheet's texel as an RGBA8 texture stores it: round(255 v).
glm::vec3 bytes(glm::vec3 v) { return glm::round(v * 255.0f) / 255.0f; }

// grid.png as the sheet describes it: texel (i, j), j = 0 the bottom row.
glm::vec3 grid_texel(int i, int j) {
    const float b = (i / 8 + j / 8) % 2 == 0 ? 0.6f : 0.2f;
    return bytes({(float(i) + 0.5f) / 64.0f, (float(j) + 0.5f) / 32.0f, b});
}
Level grid_texture() {
    Level grid(64, 32);
    for (int j = 0; j < 32; ++j)
        for (int i = 0; i < 64; ++i) grid.at(i, j) = grid_texel(i, j);
    return grid;
}

// Every texel of `img` (w x h) within rounding (half a step) of `sheet(i, j)`.
template <class Sheet>
void check_texels(const char* what, const fw::Image& img, int w, int h, Sheet sheet) {
    INFO(std::string(what));
    REQUIRE(img.width == w);
    REQUIRE(img.height == h);
    PixelTally tally{what, 0.5f / 255.0f + 1e-6f};
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) tally.check(i, j, sheet(i, j), rgb(img, i, j));
    tally.require(long(w) * h);
}

// --- scene=coordinates -----------------------------------------------------

const glm::vec3 kEye{0.0f, 0.0f, 3.0f};
const glm::vec3 kLight = glm::normalize(glm::vec3(1.0f, 1.0f, 1.0f));
constexpr float kAmbient = 0.2f, kDiffuse = 0.8f;

glm::mat4 sphere_clip() {
    return glm::perspective(glm::radians(45.0f), 1.0f, 0.1f, 100.0f) *
           glm::lookAt(kEye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

// The sphere's outline in the window: a circle about (256, 256) whose radius
// is tan(asin(1/3)) / tan(22.5 degrees) in NDC.
const float kOutline = 256.0f * std::tan(std::asin(1.0f / 3.0f)) / std::tan(glm::radians(22.5f));

// The point p of the unit sphere that window point w sees, and N.V there.
bool sphere_hit(glm::vec2 w, glm::vec3& p, float& n_dot_v) {
    static const glm::mat4 inverse_clip = glm::inverse(sphere_clip());
    const Ray r = ndc_ray(inverse_clip, w / (0.5f * kSize) - 1.0f);
    // |o + t d|^2 = 1 with |d| = 1: t^2 + 2 (o.d) t + |o|^2 - 1 = 0.
    const float b = glm::dot(r.origin, r.direction);
    const float disc = b * b - (glm::dot(r.origin, r.origin) - 1.0f);
    if (disc < 0) return false;
    p = r.origin + (-b - std::sqrt(disc)) * r.direction;
    n_dot_v = glm::dot(p, glm::normalize(kEye - p));
    return true;
}

// The sheet's mappings of an object-space point p, in double precision.
glm::vec2 ref_planar(glm::vec3 p) { return glm::vec2(0.5 * p.x + 0.5, 0.5 * p.y + 0.5); }
double longitude(glm::vec3 p) { return std::atan2(double(p.x), double(p.z)) / (2 * kPi) + 0.5; }
glm::vec2 ref_cylindrical(glm::vec3 p) { return glm::vec2(longitude(p), 0.5 * p.y + 0.5); }
glm::vec2 ref_spherical(glm::vec3 p) {
    const double r = std::sqrt(double(p.x) * p.x + double(p.y) * p.y + double(p.z) * p.z);
    if (r == 0.0) return glm::vec2(0.5f);
    return glm::vec2(longitude(p), std::asin(std::clamp(p.y / r, -1.0, 1.0)) / kPi + 0.5);
}

using MappingFn = glm::vec2 (*)(glm::vec3);

// What the sphere shows: (s, t) by `st`, the texture read GL_NEAREST with
// GL_REPEAT, lit or not; pixels whose (u, v) lie less than `margin` texels
// from a texel edge, or where N.V < 0.2 (the outline, where the 5120 facets
// part from the sphere), are left out.
struct SphereLook {
    MappingFn st;
    const Level& texture;
    bool lit;
    float margin;
};

// Every pixel of a frame of scene coordinates: the sphere as `look` says,
// black 1.5 pixels or more outside its outline; then a probe at the sphere
// pixel farthest from a texel edge. The seam of atan2 (x = 0, z < 0) is at
// the back, out of sight, and s = 0 or 1 there is a texel edge anyway.
void check_sphere(const fw::Image& frame, const SphereLook& look, PixelTally& sphere) {
    PixelTally background{sphere.what + ": background", 0.0f};
    glm::ivec2 best(-1);
    float best_margin = -1.0f;
    glm::vec3 best_expected(0.0f);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (glm::distance(centre(x, y), glm::vec2(256.0f)) > kOutline + 1.5f) {
                background.check(x, y, glm::vec3(0.0f), rgb(frame, x, y));
                continue;
            }
            glm::vec3 p;
            float n_dot_v = 0.0f;
            if (!sphere_hit(centre(x, y), p, n_dot_v) || n_dot_v < 0.2f) continue;
            const glm::vec2 st = look.st(p);
            const glm::vec2 uv = st * glm::vec2(look.texture.width, look.texture.height);
            const float margin = glm::min(from_edge(uv.x), from_edge(uv.y));
            if (margin < look.margin) continue;
            glm::vec3 expected = nearest(look.texture, st, Wrap::Repeat);
            if (look.lit)
                expected =
                    stored(expected * (kAmbient + kDiffuse * glm::max(glm::dot(p, kLight), 0.0f)));
            sphere.check(x, y, expected, rgb(frame, x, y));
            if (margin > best_margin) best_margin = margin, best = {x, y}, best_expected = expected;
        }
    // 512^2 pixels, less the disc of radius kOutline + 1.5 (about 151000).
    background.require(110000);
    REQUIRE(best.x >= 0);
    CHECK(fw::test::probe_rgb(frame, best.x, best.y, best_expected, sphere.tol));
}

Level checker() { return Level(texture_mapping::sphere_checker()); }

fw::RenderOutput render_sphere(Lab& lab, const std::string& mapping, bool image, bool lit) {
    return lab.render({{"scene", "coordinates"},
                       {"mapping", mapping},
                       {"image", image ? "true" : "false"},
                       {"lit", lit ? "true" : "false"}});
}

}  // namespace

TEST_CASE("texture_mapping: the declaration has the sheet's parameters and defaults") {
    const fw::RegisteredLab& lab = fw::test::this_lab();
    const fw::ParamValues p = fw::default_params(lab);
    CHECK(p.text("scene") == "coordinates");
    CHECK(p.text("mapping") == "spherical");
    CHECK_FALSE(p.flag("image"));
    CHECK_FALSE(p.flag("lit"));
    CHECK(p.text("wrap") == "repeat");
    CHECK(p.text("mag_filter") == "nearest");
    CHECK(p.text("min_filter") == "nearest");
    CHECK(p.text("maps") == "modulate");
    using Names = std::vector<std::string>;
    Names names;
    for (const fw::Param& param : lab.info.params) {
        INFO("parameter " << param.name);
        names.push_back(param.name);
        CHECK(!param.help_text.empty());
        CHECK(param.shortcut != 0);
        if (param.name == "scene")
            CHECK(param.choices ==
                  Names{"coordinates", "perspective", "wrap", "magnify", "minify", "lightmap"});
        if (param.name == "mapping")
            CHECK(param.choices == Names{"vertex", "planar", "cylindrical", "spherical"});
        if (param.name == "wrap")
            CHECK(param.choices ==
                  Names{"repeat", "mirrored_repeat", "clamp_to_edge", "clamp_to_border"});
        if (param.name == "mag_filter") CHECK(param.choices == Names{"nearest", "linear"});
        if (param.name == "min_filter")
            CHECK(param.choices ==
                  Names{"nearest", "linear", "nearest_mipmap_nearest", "linear_mipmap_linear"});
        if (param.name == "maps") CHECK(param.choices == Names{"base", "light", "modulate"});
    }
    CHECK(names ==
          Names{"scene", "mapping", "image", "lit", "wrap", "mag_filter", "min_filter", "maps"});
}

TEST_CASE("texture_mapping: the textures are the sheet's, texel by texel") {
    using namespace texture_mapping;
    const auto sphere = [](int i, int j) {
        return bytes((i + j) % 2 == 0 ? glm::vec3(0.9f) : glm::vec3(0.8f, 0.2f, 0.1f));
    };
    check_texels("sphere_checker", sphere_checker(), 16, 8, sphere);
    const auto floor = [](int i, int j) {
        return bytes(glm::vec3((i + j) % 2 == 0 ? 0.9f : 0.1f));
    };
    check_texels("floor_checker", floor_checker(), 8, 8, floor);
    const auto ramp_texel = [](int i, int j) {
        return bytes({(2.0f * i + 1.0f) / 8.0f, (2.0f * j + 1.0f) / 8.0f, 0.25f});
    };
    check_texels("ramp", ramp(), 4, 4, ramp_texel);
    const auto fine = [](int i, int j) { return glm::vec3((i + j) % 2 == 0 ? 1.0f : 0.0f); };
    check_texels("fine_checker", fine_checker(), 256, 256, fine);
    const auto base = [](int i, int j) {
        return bytes((i + j) % 2 == 0 ? glm::vec3(0.9f, 0.7f, 0.3f) : glm::vec3(0.5f, 0.3f, 0.1f));
    };
    check_texels("base_texture", base_texture(), 8, 8, base);
    const auto light = [](int i, int j) {
        const float d = glm::distance(glm::vec2(i + 0.5f, j + 0.5f) / 16.0f, glm::vec2(0.5f));
        return bytes(glm::vec3(std::max(0.15f, 1.0f - 1.5f * d)));
    };
    check_texels("light_map", light_map(), 16, 16, light);
    // The file itself, read by the framework (bottom row first): the sheet's
    // description of grid.png, which the image tests below expect.
    const fw::Image file = fw::read_png(fw::shader_path(std::string(FW_LAB_DIR) + "/grid.png"));
    check_texels("grid.png", file, 64, 32, grid_texel);
}

TEST_CASE("texture_mapping: coordinates: planar, cylindrical and spherical at every pixel") {
    Lab lab;
    const Level texture = checker();
    const std::pair<const char*, MappingFn> mappings[] = {
        {"planar", &ref_planar}, {"cylindrical", &ref_cylindrical}, {"spherical", &ref_spherical}};
    for (const auto& [name, fn] : mappings) {
        const std::string mapping = name;
        CAPTURE(mapping);
        const fw::RenderOutput out = render_sphere(lab, mapping, false, false);
        PixelTally sphere{"coordinates, " + mapping, 1.0f / 255.0f};
        check_sphere(out.color, {fn, texture, false, 0.1f}, sphere);
        // The sphere covers about 150000 pixels, 120000 where N.V >= 0.2.
        sphere.require(90000);
    }
}

TEST_CASE("texture_mapping: coordinates: per-vertex coordinates, away from the texel edges") {
    Lab lab;
    const Level texture = checker();
    const fw::RenderOutput out = render_sphere(lab, "vertex", false, false);
    // Within a facet the lab interpolates the vertices' (s, t); the exact
    // mapping bends, so only pixels 0.3 texel or more from an edge are sure.
    PixelTally sphere{"coordinates, vertex", 1.0f / 255.0f};
    check_sphere(out.color, {&ref_spherical, texture, false, 0.3f}, sphere);
    sphere.require(20000);
}

TEST_CASE("texture_mapping: coordinates: lit, the texture is the diffuse colour") {
    Lab lab;
    const Level checkerboard = checker(), grid = grid_texture();
    for (const bool image : {false, true}) {
        CAPTURE(image);
        const fw::RenderOutput out = render_sphere(lab, "spherical", image, true);
        // The facets' interpolated normal strays a little from the sphere's
        // (1/255 at most, measured, with the buffer's rounding): 2 steps.
        PixelTally sphere{image ? "coordinates, lit image" : "coordinates, lit", 2.0f / 255.0f};
        check_sphere(out.color, {&ref_spherical, image ? grid : checkerboard, true, 0.1f}, sphere);
        sphere.require(90000);
    }
}

TEST_CASE("texture_mapping: coordinates: the image file, bottom row at t = 0") {
    Lab lab;
    const Level grid = grid_texture();
    for (const std::string mapping : {"spherical", "planar"}) {
        CAPTURE(mapping);
        const fw::RenderOutput out = render_sphere(lab, mapping, true, false);
        PixelTally sphere{"coordinates, image, " + mapping, 1.0f / 255.0f};
        check_sphere(out.color,
                     {mapping == "planar" ? &ref_planar : &ref_spherical, grid, false, 0.1f},
                     sphere);
        sphere.require(80000);
        // Green grows with t: the sphere's top is greener than its bottom.
        const int top = int(256 + 0.8f * kOutline), bottom = int(256 - 0.8f * kOutline);
        const glm::vec3 up = rgb(out.color, 256, top), down = rgb(out.color, 256, bottom);
        MESSAGE("green at (256, " << top << "): " << up.g << ", at (256, " << bottom
                                  << "): " << down.g);
        CHECK(up.g > down.g + 0.3f);
    }
}

TEST_CASE("texture_mapping: planar(), cylindrical() and spherical() are the sheet's mappings") {
    std::mt19937 random(8);
    std::uniform_real_distribution<float> coordinate(-2.0f, 2.0f);
    std::vector<glm::vec3> points = {{0, 0, 1},    {1, 0, 0},  {-1, 0, 0},
                                     {0, 1, 0},    {0, -1, 0}, {0.5f, 0.5f, 0.5f},
                                     {0, 0.5f, 0}, {3, -4, 0}, {0, 0, 0}};
    while (points.size() < 500) {
        const glm::vec3 p(coordinate(random), coordinate(random), coordinate(random));
        // Not on the seam, x = 0 behind (z < 0), where s jumps from 1 to 0.
        if (std::fabs(p.x) > 1e-3f || p.z > 0) points.push_back(p);
    }
    const std::pair<const char*, std::pair<MappingFn, MappingFn>> functions[] = {
        {"planar", {&texture_mapping::planar, &ref_planar}},
        {"cylindrical", {&texture_mapping::cylindrical, &ref_cylindrical}},
        {"spherical", {&texture_mapping::spherical, &ref_spherical}}};
    for (const auto& [function, fns] : functions) {
        const std::string name = function;
        long failed = 0;
        for (const glm::vec3 p : points) {
            const glm::vec2 expected = fns.second(p), observed = fns.first(p);
            if (glm::all(glm::lessThanEqual(glm::abs(expected - observed), glm::vec2(1e-5f))))
                continue;
            if (++failed <= 5)
                MESSAGE(name << "(" << p.x << ", " << p.y << ", " << p.z << "): expected ("
                             << expected.x << ", " << expected.y << ") observed (" << observed.x
                             << ", " << observed.y << ")");
        }
        MESSAGE(name << "(): " << failed << " of " << points.size() << " points wrong");
        CHECK(failed == 0);
    }
    // The reference at fixed points: the front (0, 0, 1) is the middle of the
    // texture, +x a quarter turn further, the north pole t = 1; and the lab's
    // spherical() at the origin, which has no direction: (0.5, 0.5).
    CHECK(ref_spherical({0, 0, 1}) == glm::vec2(0.5f, 0.5f));
    CHECK(ref_spherical({1, 0, 0}) == glm::vec2(0.75f, 0.5f));
    CHECK(ref_spherical({0, 2, 0}).y == 1.0f);
    CHECK(ref_cylindrical({0, 0.5f, 0}) == glm::vec2(0.5f, 0.75f));
    CHECK(texture_mapping::spherical(glm::vec3(0.0f)) == glm::vec2(0.5f, 0.5f));
}

TEST_CASE("texture_mapping: a frame depends on its parameters, not on the frames before it") {
    // Each frame sets the sampler state it reads (wrap, filters, mipmaps,
    // texture units), which stays with the texture objects afterwards.
    Lab lab;
    const std::vector<fw::test::Settings> frames = {
        {{"scene", "minify"}, {"min_filter", "linear_mipmap_linear"}},
        {{"scene", "coordinates"}, {"image", "true"}, {"lit", "true"}},
        {{"scene", "lightmap"}},
        {{"scene", "wrap"}, {"wrap", "clamp_to_border"}},
        {{"scene", "minify"}},
        {{"scene", "magnify"}, {"mag_filter", "linear"}},
        {{"scene", "perspective"}},
        {{"scene", "wrap"}},
        {{"scene", "coordinates"}, {"mapping", "vertex"}},
        {{"scene", "magnify"}}};
    std::vector<fw::Image> forward;
    for (const fw::test::Settings& s : frames) forward.push_back(lab.render(s).color);
    // The same frames again, in the reverse order.
    for (size_t k = frames.size(); k-- > 0;) {
        const fw::Image again = lab.render(frames[k]).color;
        long differ = 0;
        for (size_t i = 0; i < again.pixels.size(); ++i)
            differ += again.pixels[i] != forward[k].pixels[i];
        MESSAGE("frame " << k << " (scene " << frames[k][0].second << "): " << differ
                         << " pixels differ between the two orders");
        CHECK(differ == 0);
    }
}

TEST_CASE("texture_mapping: checkpoints.json: its probes and stats hold for the solution") {
    Lab lab;
    std::vector<std::string> scenes;
    fw::test::for_each_checkpoint(
        lab.lab, lab.renderer, 6,
        [&](const fw::Checkpoint& cp, const fw::ParamValues& params, const fw::RenderOutput& out) {
            scenes.push_back(params.text("scene"));
            fw::test::check_probes_and_stats(cp.checks, out);
        });
    for (const std::string scene :
         {"coordinates", "perspective", "wrap", "magnify", "minify", "lightmap"}) {
        INFO("scene " << scene);
        CHECK(std::count(scenes.begin(), scenes.end(), scene) >= 1);
    }
}
