// Lab 8 `texture-mapping`: the scenes perspective, wrap, magnify, minify and
// lightmap, and the unit function level_of_detail(). Every expectation is
// computed here from the sheet's numbers (labs/08_texture_mapping/README.md)
// with GL's texture rules (GL 4.3 core, sections 8.14.1 to 8.14.4), never
// read from a reference image or from the lab's own code.
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <string>
#include <vector>

#include "mappings.hpp"
#include "texture_mapping_test.hpp"
#include "textures.hpp"

using namespace texture_mapping_test;
using texture_mapping::MinFilter;
using texture_mapping::Wrap;

namespace {

float cross(glm::vec2 u, glm::vec2 v) { return u.x * v.y - u.y * v.x; }

// Barycentric coordinates of p in the window triangle (a, b, c).
glm::vec3 barycentric(glm::vec2 p, glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    const float area = cross(b - a, c - a);
    return {cross(b - p, c - p) / area, cross(c - p, a - p) / area, cross(a - p, b - p) / area};
}

// --- scene=perspective -----------------------------------------------------

// The floor's corners, its (s, t) = ((x + 2) / 4, (-z - 4) / 12), its triangles.
const glm::vec3 kFloor[4] = {{-2, -1, -4}, {2, -1, -4}, {2, -1, -16}, {-2, -1, -16}};
glm::vec2 floor_st(glm::vec3 p) { return {(p.x + 2.0f) / 4.0f, (-p.z - 4.0f) / 12.0f}; }
const int kFloorTriangles[2][3] = {{0, 1, 2}, {0, 2, 3}};

// Each half of the frame is a 256 x 512 viewport; the camera's aspect is 1/2.
constexpr int kHalf = kSize / 2;
glm::vec2 half_ndc(glm::vec2 w) {
    return {w.x / (0.5f * kHalf) - 1.0f, w.y / (0.5f * kSize) - 1.0f};
}

// The camera, once: the inverse of P * V for the ray cast, and the corners in
// a half's window coordinates (all are in front of the eye, w > 0).
struct FloorCamera {
    glm::mat4 clip = glm::perspective(glm::radians(60.0f), 0.5f, 0.1f, 100.0f) *
                     glm::lookAt(glm::vec3(0, 1.5f, -1), glm::vec3(0, -1, -9), glm::vec3(0, 1, 0));
    glm::mat4 inverse_clip = glm::inverse(clip);
    glm::vec2 corners[4];
    FloorCamera() {
        for (int i = 0; i < 4; ++i) {
            const glm::vec4 c = clip * glm::vec4(kFloor[i], 1.0f);
            REQUIRE(c.w > 0.0f);
            corners[i] = (glm::vec2(c) / c.w + 1.0f) * 0.5f * glm::vec2(kHalf, kSize);
        }
    }
};
const FloorCamera& floor_camera() {
    static const FloorCamera camera;
    return camera;
}

// Perspective-correct: the (s, t) of the floor point the ray through window
// point w of a half meets; false off the floor.
bool correct_st(glm::vec2 w, glm::vec2& st) {
    const Ray r = ndc_ray(floor_camera().inverse_clip, half_ndc(w));
    if (r.direction.y >= 0.0f) return false;
    const glm::vec3 p = r.origin + (-1.0f - r.origin.y) / r.direction.y * r.direction;
    if (p.x < -2 || p.x > 2 || p.z > -4 || p.z < -16) return false;
    st = floor_st(p);
    return true;
}

// Affine (noperspective): the corners' (s, t) weighted by the window-space
// barycentrics of the triangle holding w (of the two, the one w is deeper in).
// The near corners lie beyond the half's sides; clipping keeps noperspective
// values linear in window coordinates (GL 4.3 section 13.5), so the
// unclipped triangles' barycentrics hold.
glm::vec2 affine_st(glm::vec2 w) {
    const glm::vec2* c = floor_camera().corners;
    glm::vec3 best(-1e9f);
    const int* tri = kFloorTriangles[0];
    for (const auto& t : kFloorTriangles) {
        const glm::vec3 b = barycentric(w, c[t[0]], c[t[1]], c[t[2]]);
        if (glm::min(b.x, glm::min(b.y, b.z)) > glm::min(best.x, glm::min(best.y, best.z)))
            best = b, tri = t;
    }
    return best.x * floor_st(kFloor[tri[0]]) + best.y * floor_st(kFloor[tri[1]]) +
           best.z * floor_st(kFloor[tri[2]]);
}

// How many of pixel (x, y)'s centre and the 8 points a pixel away see the floor.
int floor_coverage(int x, int y) {
    int n = 0;
    glm::vec2 st;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) n += correct_st(centre(x + dx, y + dy), st);
    return n;
}

bool away_from_edges(glm::vec2 uv, float margin) {
    return from_edge(uv.x) >= margin && from_edge(uv.y) >= margin;
}

// --- scenes wrap, magnify, minify and lightmap -----------------------------

// A quad [lo, hi]^2 in window coordinates with (s, t) from st_lo to st_hi.
struct Quad {
    float lo, hi, st_lo, st_hi;
    // How far window point w is inside, in pixels (negative outside).
    float inside_by(glm::vec2 w) const {
        return glm::min(glm::min(w.x - lo, hi - w.x), glm::min(w.y - lo, hi - w.y));
    }
    glm::vec2 st(glm::vec2 w) const { return st_lo + (w - lo) / (hi - lo) * (st_hi - st_lo); }
    glm::ivec2 pixel(glm::vec2 st_at) const {
        return glm::ivec2(glm::floor(lo + (st_at - st_lo) / (st_hi - st_lo) * (hi - lo)));
    }
};
// NDC [-0.9, 0.9]^2 is window [25.6, 486.4]^2.
constexpr Quad kWrapQuad{25.6f, 486.4f, -1.0f, 2.0f};
constexpr Quad kMagnifyQuad{0.0f, 512.0f, 0.0f, 1.0f};
constexpr float kHalfTexel = 0.5f / 256.0f;
constexpr Quad kMinifyQuad{192.0f, 320.0f, kHalfTexel, 1.0f + kHalfTexel};
constexpr Quad kLightmapQuad{25.6f, 486.4f, 0.0f, 1.0f};

// The level of detail of GL 4.3 section 8.14.1 for a texture of w x h
// texels: rho = max(|(ds/dx w, dt/dx h)|, |(ds/dy w, dt/dy h)|), lambda = log2(rho).
double ref_lod(glm::dvec2 d_dx, glm::dvec2 d_dy, int w, int h) {
    const glm::dvec2 size(w, h);
    return std::log2(std::max(glm::length(d_dx * size), glm::length(d_dy * size)));
}

// The minification filters at (s, t) with level of detail lambda > 0 and
// mag_filter=nearest (so c = 0), GL_REPEAT (section 8.14.3): the mipmapped
// ones pick level ceil(lambda + 1/2) - 1, or blend floor(lambda) and the next
// by frac(lambda).
glm::vec3 minified(const std::vector<Level>& levels, glm::vec2 st, float lambda, MinFilter f) {
    const int q = int(levels.size()) - 1;
    switch (f) {
        case MinFilter::Nearest:
            return nearest(levels[0], st, Wrap::Repeat);
        case MinFilter::Linear:
            return bilinear(levels[0], st, Wrap::Repeat);
        case MinFilter::NearestMipmapNearest: {
            const int d = lambda <= 0.5f ? 0 : std::min(int(std::ceil(lambda + 0.5f)) - 1, q);
            return nearest(levels[d], st, Wrap::Repeat);
        }
        case MinFilter::LinearMipmapLinear: {
            const int d1 = std::min(int(std::floor(lambda)), q), d2 = std::min(d1 + 1, q);
            const float a = lambda - std::floor(lambda);
            return (1 - a) * bilinear(levels[d1], st, Wrap::Repeat) +
                   a * bilinear(levels[d2], st, Wrap::Repeat);
        }
    }
    return glm::vec3(-1.0f);
}

}  // namespace

TEST_CASE("texture_mapping: perspective: the left half perspective-correct, the right affine") {
    Lab lab;
    const Level texture(texture_mapping::floor_checker());
    const fw::RenderOutput out = lab.render({{"scene", "perspective"}});
    PixelTally correct{"perspective, left half (perspective-correct)", 1.0f / 255.0f};
    PixelTally affine{"perspective, right half (affine)", 1.0f / 255.0f};
    PixelTally background{"perspective, background", 0.0f};
    long floor_pixels = 0, differ = 0, predicted = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kHalf; ++x) {
            const int coverage = floor_coverage(x, y);
            if (coverage == 0) {
                background.check(x, y, glm::vec3(0.0f), rgb(out.color, x, y));
                background.check(x + kHalf, y, glm::vec3(0.0f), rgb(out.color, x + kHalf, y));
            }
            if (coverage < 9) continue;
            ++floor_pixels;
            glm::vec2 st_c;
            correct_st(centre(x, y), st_c);
            const glm::vec2 st_a = affine_st(centre(x, y));
            const glm::vec3 left = rgb(out.color, x, y), right = rgb(out.color, x + kHalf, y);
            differ += max_difference(left, right) > 0.5f;
            const glm::vec3 e_c = nearest(texture, st_c, Wrap::Repeat);
            const glm::vec3 e_a = nearest(texture, st_a, Wrap::Repeat);
            const bool sure_c = away_from_edges(8.0f * st_c, 0.1f);
            const bool sure_a = away_from_edges(8.0f * st_a, 0.1f);
            if (sure_c) correct.check(x, y, e_c, left);
            if (sure_a) affine.check(x + kHalf, y, e_a, right);
            predicted += sure_c && sure_a && max_difference(e_c, e_a) > 0.5f;
        }
    MESSAGE("floor pixels in each half: " << floor_pixels << "; the halves differ at " << differ
                                          << " of them (predicted at least " << predicted << ")");
    correct.require(30000);
    affine.require(30000);
    background.require(20000);
    CHECK(predicted > 5000);
    CHECK(differ >= predicted);
    // The sheet's spot where the halves differ: dark on the left, light on
    // the right.
    const glm::ivec2 probe(197, 115);
    glm::vec2 st_c;
    REQUIRE(correct_st(centre(probe.x, probe.y), st_c));
    const glm::vec2 st_a = affine_st(centre(probe.x, probe.y));
    CHECK(away_from_edges(8.0f * st_c, 0.1f));
    CHECK(away_from_edges(8.0f * st_a, 0.1f));
    MESSAGE("pixel (" << probe.x << ", " << probe.y << "): perspective-correct (s, t) = (" << st_c.x
                      << ", " << st_c.y << "), affine (" << st_a.x << ", " << st_a.y << ")");
    bool pass =
        fw::test::probe_rgb(out.color, probe.x, probe.y, nearest(texture, st_c, Wrap::Repeat));
    pass = fw::test::probe_rgb(out.color, probe.x + kHalf, probe.y,
                               nearest(texture, st_a, Wrap::Repeat)) &&
           pass;
    CHECK(pass);
}

TEST_CASE("texture_mapping: wrap: each mode's texel at every pixel, from -1 to 2") {
    Lab lab;
    const Level ramp(texture_mapping::ramp());
    for (const auto& wrap : texture_mapping::kWraps) {
        const std::string name = wrap.name;
        CAPTURE(name);
        const fw::RenderOutput out = lab.render({{"scene", "wrap"}, {"wrap", wrap.name}});
        PixelTally quad{std::string("wrap ") + wrap.name, 1.0f / 255.0f};
        PixelTally background{"wrap, background", 0.0f};
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const float d = kWrapQuad.inside_by(centre(x, y));
                if (d < -1.0f) background.check(x, y, glm::vec3(0.0f), rgb(out.color, x, y));
                const glm::vec2 st = kWrapQuad.st(centre(x, y));
                if (d < 1.0f || !away_from_edges(4.0f * st, 0.1f)) continue;
                quad.check(x, y, nearest(ramp, st, wrap.value), rgb(out.color, x, y));
            }
        // 459^2 pixels, less 3.8 pixels either side of each of the 11 texel
        // edges along each axis: 0.8 of each texel's 38.4.
        quad.require(130000);
        background.require(40000);
        // In three of the nine copies: left of the texture, above and right
        // of it, and inside it.
        bool pass = true;
        for (const glm::vec2 st :
             {glm::vec2(-0.375f, 0.625f), glm::vec2(1.625f, 1.375f), glm::vec2(0.375f, 0.875f)}) {
            const glm::ivec2 p = kWrapQuad.pixel(st);
            MESSAGE("(s, t) = (" << st.x << ", " << st.y << ") at pixel (" << p.x << ", " << p.y
                                 << ")");
            pass = fw::test::probe_rgb(out.color, p.x, p.y, nearest(ramp, st, wrap.value)) && pass;
        }
        CHECK(pass);
    }
}

TEST_CASE("texture_mapping: magnify: nearest and bilinear filtering at every pixel") {
    Lab lab;
    const Level ramp(texture_mapping::ramp());
    for (const bool linear : {false, true}) {
        CAPTURE(linear);
        const fw::RenderOutput out =
            lab.render({{"scene", "magnify"}, {"mag_filter", linear ? "linear" : "nearest"}});
        // Bilinear weights have 8 bits of fraction on llvmpipe: with 64/255
        // between neighbouring texels that is a quarter of a step at most,
        // then the buffer rounds (measured: 0.5/255).
        PixelTally tally{linear ? "magnify linear" : "magnify nearest", 1.0f / 255.0f};
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const glm::vec2 st = kMagnifyQuad.st(centre(x, y));
                tally.check(x, y,
                            linear ? bilinear(ramp, st, Wrap::ClampToEdge)
                                   : nearest(ramp, st, Wrap::ClampToEdge),
                            rgb(out.color, x, y));
            }
        tally.require(long(kSize) * kSize);
        // A texel's centre reads the texel with either filter; a quarter of
        // the way to the next texel's centre, bilinear weighs them 3:1.
        const glm::vec3 t11 = ramp.at(1, 1), t21 = ramp.at(2, 1);
        bool pass = fw::test::probe_rgb(out.color, 192, 192, t11);
        pass = fw::test::probe_rgb(out.color, 224, 192, linear ? 0.75f * t11 + 0.25f * t21 : t11) &&
               pass;
        CHECK(pass);
    }
}

TEST_CASE("texture_mapping: minify: level 0 aliases to white, level 1 is grey") {
    Lab lab;
    std::vector<Level> levels{Level(texture_mapping::fine_checker())};
    while (levels.back().width > 1) levels.push_back(levels.back().half());
    REQUIRE(levels.size() == 9);
    // 256 texels over 128 pixels along each axis.
    const float lambda = float(ref_lod({1.0 / 128, 0}, {0, 1.0 / 128}, 256, 256));
    CHECK(lambda == 1.0f);
    for (const auto& filter : texture_mapping::kMinFilters) {
        const std::string name = filter.name;
        CAPTURE(name);
        const fw::RenderOutput out = lab.render({{"scene", "minify"}, {"min_filter", filter.name}});
        PixelTally quad{std::string("minify ") + filter.name, 1.0f / 255.0f};
        PixelTally background{"minify, background", 0.0f};
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const glm::vec2 w = centre(x, y);
                if (kMinifyQuad.inside_by(w) < 0)
                    background.check(x, y, glm::vec3(0.0f), rgb(out.color, x, y));
                else
                    quad.check(x, y, minified(levels, kMinifyQuad.st(w), lambda, filter.value),
                               rgb(out.color, x, y));
            }
        quad.require(128 * 128);
        background.require(kSize * kSize - 128 * 128);
        // Pixel (192, 192) samples the centre of texel (1, 1): white; level 1 is grey.
        const bool mipmapped = filter.value == MinFilter::NearestMipmapNearest ||
                               filter.value == MinFilter::LinearMipmapLinear;
        CHECK(fw::test::probe_rgb(out.color, 192, 192, glm::vec3(mipmapped ? 0.5f : 1.0f)));
    }
}

TEST_CASE("texture_mapping: lightmap: the base, the light map and their product") {
    Lab lab;
    const Level base(texture_mapping::base_texture()), light(texture_mapping::light_map());
    for (const std::string maps : {"base", "light", "modulate"}) {
        CAPTURE(maps);
        const fw::RenderOutput out = lab.render({{"scene", "lightmap"}, {"maps", maps}});
        PixelTally quad{"lightmap " + maps, 1.0f / 255.0f};
        PixelTally background{"lightmap, background", 0.0f};
        const auto expected = [&](glm::vec2 st) {
            const glm::vec3 b = nearest(base, st, Wrap::ClampToEdge);
            const glm::vec3 l = nearest(light, st, Wrap::ClampToEdge);
            return maps == "base" ? b : maps == "light" ? l : stored(b * l);
        };
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const float d = kLightmapQuad.inside_by(centre(x, y));
                if (d < -1.0f) background.check(x, y, glm::vec3(0.0f), rgb(out.color, x, y));
                const glm::vec2 st = kLightmapQuad.st(centre(x, y));
                // 0.1 texel of the light map is 2.9 pixels.
                if (d < 1.0f || !away_from_edges(16.0f * st, 0.1f)) continue;
                quad.check(x, y, expected(st), rgb(out.color, x, y));
            }
        quad.require(130000);
        background.require(40000);
        // The middle, where the light map is brightest, and a corner, where
        // it is 0.15.
        bool pass = true;
        for (const glm::vec2 st : {glm::vec2(0.53f, 0.47f), glm::vec2(0.03f, 0.97f)}) {
            const glm::ivec2 p = kLightmapQuad.pixel(st);
            pass = fw::test::probe_rgb(out.color, p.x, p.y, expected(st)) && pass;
        }
        CHECK(pass);
    }
}

TEST_CASE("texture_mapping: level_of_detail() is log2 of the pixel's longer side in texels") {
    // Exact cases: 2 texels per pixel is level 1, one texel level 0, half a
    // texel -1 (magnified); the longer side counts, and so does the height.
    struct Case {
        glm::vec2 d_dx, d_dy;
        int width, height;
        float lambda;
    };
    const Case cases[] = {{{2.0f / 256, 0}, {0, 2.0f / 256}, 256, 256, 1.0f},
                          {{1.0f / 64, 0}, {0, 1.0f / 64}, 64, 64, 0.0f},
                          {{0.5f / 256, 0}, {0, 0.5f / 256}, 256, 256, -1.0f},
                          {{8.0f / 256, 0}, {0, 1.0f / 256}, 256, 256, 3.0f},
                          {{0, 1.0f / 256}, {0, 4.0f / 32}, 256, 32, 2.0f},
                          {{3.0f / 64, 4.0f / 64}, {0, 0}, 64, 64, std::log2(5.0f)},
                          {{-1.0f / 16, 0}, {0, -1.0f / 8}, 32, 64, 3.0f}};
    for (const Case& c : cases) {
        const float observed = texture_mapping::level_of_detail(c.d_dx, c.d_dy, c.width, c.height);
        MESSAGE("level_of_detail((" << c.d_dx.x << ", " << c.d_dx.y << "), (" << c.d_dy.x << ", "
                                    << c.d_dy.y << "), " << c.width << ", " << c.height
                                    << "): expected " << c.lambda << " observed " << observed);
        CHECK(std::fabs(observed - c.lambda) <= 1e-5f);
    }
    std::mt19937 random(8);
    std::uniform_real_distribution<float> exponent(-5.0f, -0.5f), sign(-1.0f, 1.0f);
    std::uniform_int_distribution<int> size(1, 1024);
    const auto derivative = [&] {
        return std::copysign(std::pow(10.0f, exponent(random)), sign(random));
    };
    long failed = 0;
    for (int k = 0; k < 1000; ++k) {
        const glm::vec2 d_dx(derivative(), derivative()), d_dy(derivative(), derivative());
        const int w = size(random), h = size(random);
        const double expected = ref_lod(d_dx, d_dy, w, h);
        const float observed = texture_mapping::level_of_detail(d_dx, d_dy, w, h);
        if (std::fabs(observed - expected) <= 1e-4) continue;
        if (++failed <= 5)
            MESSAGE("level_of_detail((" << d_dx.x << ", " << d_dx.y << "), (" << d_dy.x << ", "
                                        << d_dy.y << "), " << w << ", " << h << "): expected "
                                        << expected << " observed " << observed);
    }
    MESSAGE("level_of_detail(): " << failed << " of 1000 random calls wrong");
    CHECK(failed == 0);
}
