// Lab 7 `framebuffer-ops`: the scenes stencil, faces and scissor, and the
// state a frame leaves to the next. Every expectation is computed here from
// the sheet's numbers (scenes.hpp) with GL's rules, a ray cast for the box,
// never read from a reference image or from the lab's own code.
#include <algorithm>
#include <string>
#include <vector>

#include "framebuffer_ops_test.hpp"
#include "framework/gl/framebuffer.hpp"

using namespace framebuffer_ops_test;
using namespace framebuffer_ops;

namespace {

// --- scene=stencil ---------------------------------------------------------

// GL at NDC point p: the bands inside the mask disc (stencil 1), the white
// outline disc where the stencil is 0 (with outline on), black elsewhere.
glm::vec3 stencil_pixel(glm::vec2 p, bool outline) {
    const float r = glm::length(p);
    if (r < kMaskRadius)
        for (const Band& b : bands())
            if (p.y >= b.y0 && p.y < b.y1) return b.color;
    if (outline && r >= kMaskRadius && r < kOutlineRadius) return kOutlineColor;
    return glm::vec3(0.0f);
}

// --- scene=faces -----------------------------------------------------------

struct Triangle {
    glm::vec3 a, b, c;
    bool front;  // counter-clockwise in window coordinates (glFrontFace(GL_CCW))
};

// The box's 10 triangles in gl_PrimitiveID order: each face's vertices
// 0, 1, 2, 3 make (0, 1, 2) and (0, 2, 3).
std::vector<Triangle> box_triangles() {
    const std::vector<Vertex> v = box_vertices();
    const glm::mat4 clip = box_view_projection();
    std::vector<Triangle> out;
    for (int f = 0; f < 5; ++f)
        for (const glm::ivec3 k : {glm::ivec3(0, 1, 2), glm::ivec3(0, 2, 3)}) {
            Triangle t{v[4 * f + k[0]].position, v[4 * f + k[1]].position, v[4 * f + k[2]].position,
                       false};
            // GL's facing rule: the sign of the triangle's area in window
            // coordinates.
            const glm::vec2 a(to_window(clip * glm::vec4(t.a, 1)));
            const glm::vec2 b(to_window(clip * glm::vec4(t.b, 1)));
            const glm::vec2 c(to_window(clip * glm::vec4(t.c, 1)));
            const glm::vec2 u = b - a, w = c - a;
            t.front = u.x * w.y - u.y * w.x > 0.0f;
            out.push_back(t);
        }
    return out;
}

// What the ray through window point p hits first: the triangle's index
// (-1: none) and the point, of every triangle or only the front-facing ones.
struct Hit {
    int triangle = -1;
    glm::vec3 point{0.0f};
};
Hit cast(const std::vector<Triangle>& triangles, const glm::mat4& inverse_clip, glm::vec2 p,
         bool front_only) {
    const glm::vec2 ndc = p / (0.5f * kSize) - 1.0f;
    const glm::vec4 n = inverse_clip * glm::vec4(ndc, -1, 1),
                    f = inverse_clip * glm::vec4(ndc, 1, 1);
    const glm::vec3 origin = glm::vec3(n) / n.w, dir = glm::vec3(f) / f.w - origin;
    Hit hit;
    float nearest = 2.0f;
    for (size_t i = 0; i < triangles.size(); ++i) {
        const Triangle& t = triangles[i];
        if (front_only && !t.front) continue;
        // Moller-Trumbore: origin + s dir = a + u (b - a) + v (c - a).
        const glm::vec3 e1 = t.b - t.a, e2 = t.c - t.a, q = glm::cross(dir, e2);
        const float det = glm::dot(e1, q);
        if (std::fabs(det) < 1e-12f) continue;
        const glm::vec3 o = origin - t.a, r = glm::cross(o, e1);
        const float u = glm::dot(o, q) / det, v = glm::dot(dir, r) / det;
        const float s = glm::dot(e2, r) / det;
        if (u < 0 || v < 0 || u + v > 1 || s <= 0 || s >= nearest) continue;
        nearest = s;
        hit = {int(i), origin + s * dir};
    }
    return hit;
}

// The hit of every pixel whose centre and the points 1.5 pixels away along x
// and y see the same triangle (or none); `valid` false for the others.
struct HitMap {
    std::vector<Hit> hits;
    std::vector<bool> valid;
};
HitMap hit_map(bool cull) {
    const std::vector<Triangle> triangles = box_triangles();
    const glm::mat4 inverse_clip = glm::inverse(box_view_projection());
    HitMap map{std::vector<Hit>(kSize * kSize), std::vector<bool>(kSize * kSize)};
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const Hit h = cast(triangles, inverse_clip, centre(x, y), cull);
            bool same = true;
            for (const glm::vec2 d :
                 {glm::vec2(1.5f, 0), glm::vec2(-1.5f, 0), glm::vec2(0, 1.5f), glm::vec2(0, -1.5f)})
                same &=
                    cast(triangles, inverse_clip, centre(x, y) + d, cull).triangle == h.triangle;
            map.hits[y * kSize + x] = h;
            map.valid[y * kSize + x] = same;
        }
    return map;
}

const glm::vec3 kOutside{0.9f, 0.5f, 0.1f}, kInside{0.1f, 0.5f, 0.9f};
const glm::vec3 kLight{0.9f}, kDark{0.2f};

// The colour faces.frag gives pixel (x, y) seeing `hit` of triangle t;
// false where the pattern is too close to a change of colour to say.
bool faces_color(const std::string& pattern, const Triangle& t, int id, int x, int y, glm::vec3 hit,
                 glm::vec3& color) {
    if (pattern == "facing") {
        color = t.front ? kOutside : kInside;
    } else if (pattern == "primitive") {
        color = glm::vec3(float(id + 1) / 10.0f);
    } else if (pattern == "screen") {
        color = (x / 32 + y / 32) % 2 == 0 ? kLight : kDark;
    } else {
        const glm::vec3 s = 4.0f * hit + 0.5f;
        const glm::vec3 off = glm::abs(s - glm::round(s));
        if (glm::min(off.x, glm::min(off.y, off.z)) < 0.05f) return false;
        const glm::ivec3 c(glm::floor(s));
        color = ((c.x + c.y + c.z) % 2 + 2) % 2 == 0 ? kLight : kDark;
    }
    return true;
}

// --- scene=scissor ---------------------------------------------------------

// GL at pixel (x, y) of scene scissor in a frame whose scene viewport is v
// (x, y, width, height): the rectangles, given for 512 x 512, scale with the
// viewport. A clear obeys the scissor test but not the viewport; a draw both.
glm::vec3 scissor_pixel(glm::ivec4 v, bool scissor, int x, int y) {
    const float s = float(v[2]) / 512.0f;
    const auto in = [&](glm::ivec4 r) {
        const float x0 = float(v[0]) + s * float(r[0]), y0 = float(v[1]) + s * float(r[1]);
        return x >= x0 && x < x0 + s * float(r[2]) && y >= y0 && y < y0 + s * float(r[3]);
    };
    const bool in_viewport = in({0, 0, 512, 512});
    if (in_viewport && (!scissor || in(kDrawRect))) return kScissorDraw;
    if (!scissor || in(kClearRect)) return kScissorClear;
    return glm::vec3(0.0f);
}

}  // namespace

TEST_CASE("framebuffer_ops: stencil: the bands only inside the mask, the outline only around it") {
    Lab lab;
    for (const bool outline : {true, false}) {
        CAPTURE(outline);
        const fw::RenderOutput out =
            lab.render({{"scene", "stencil"}, {"outline", outline ? "true" : "false"}});
        const int middle = pixel(0.0f);
        const glm::vec3 white = outline ? glm::vec3(kOutlineColor) : glm::vec3(0.0f);
        bool pass = true;
        pass = fw::test::probe_rgb(out.color, middle, pixel(-0.35f), bands()[0].color) && pass;
        pass = fw::test::probe_rgb(out.color, middle, middle, bands()[1].color) && pass;
        pass = fw::test::probe_rgb(out.color, middle, pixel(0.35f), bands()[2].color) && pass;
        pass = fw::test::probe_rgb(out.color, pixel(0.55f), middle, white) && pass;
        pass = fw::test::probe_rgb(out.color, middle, pixel(-0.55f), white) && pass;
        // The bands span the frame's width; outside the mask they are not drawn.
        pass = fw::test::probe_rgb(out.color, pixel(-0.8f), middle, glm::vec3(0.0f)) && pass;
        pass = fw::test::probe_rgb(out.color, middle, pixel(0.8f), glm::vec3(0.0f)) && pass;
        CHECK(pass);
        // Every pixel 1.5 pixels or more from the discs' rims (the 64-gon
        // strays 0.15 pixel from the circle) and a pixel from the bands' edges.
        PixelTally tally{"stencil", 1.0f / 255.0f};
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const glm::vec2 p(centre_ndc(x), centre_ndc(y));
                const float r = glm::length(p), px = 2.0f / kSize;
                if (std::fabs(r - kMaskRadius) < 1.5f * px ||
                    std::fabs(r - kOutlineRadius) < 1.5f * px)
                    continue;
                if (std::fabs(std::fabs(p.y) - 0.2f) < px) continue;
                tally.check(x, y, stencil_pixel(p, outline), rgb(out.color, x, y));
            }
        tally.require(250000);
    }
}

TEST_CASE("framebuffer_ops: faces: facing, primitive ids, window and object coordinates") {
    Lab lab;
    for (const bool cull : {false, true}) {
        CAPTURE(cull);
        const HitMap map = hit_map(cull);
        const std::vector<Triangle> triangles = box_triangles();
        for (const std::string pattern : {"facing", "primitive", "screen", "object"}) {
            CAPTURE(pattern);
            const fw::RenderOutput out = lab.render(
                {{"scene", "faces"}, {"cull", cull ? "true" : "false"}, {"pattern", pattern}});
            PixelTally box{"faces " + pattern + (cull ? ", culled" : ""), 2.0f / 255.0f};
            PixelTally background{"background", 0.0f};
            long front = 0, back = 0;
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x) {
                    if (!map.valid[y * kSize + x]) continue;
                    const Hit& h = map.hits[y * kSize + x];
                    glm::vec3 color(0.0f);
                    if (h.triangle < 0) {
                        background.check(x, y, color, rgb(out.color, x, y));
                        continue;
                    }
                    const Triangle& t = triangles[h.triangle];
                    if (!faces_color(pattern, t, h.triangle, x, y, h.point, color)) continue;
                    (t.front ? front : back) += 1;
                    box.check(x, y, color, rgb(out.color, x, y));
                }
            MESSAGE("front-facing pixels tested: " << front << ", back-facing: " << back);
            box.require(cull ? 20000 : 50000);
            background.require(100000);
            CHECK(front > 10000);
            CHECK((back > 10000) == !cull);
        }
    }
}

TEST_CASE("framebuffer_ops: faces: the box's front and right faces face the eye") {
    // The eye is outside +x, +y and +z: it sees the outsides of the front and
    // right faces and the insides of the back, left and bottom faces, if each
    // face is counter-clockwise seen from outside.
    const std::vector<Triangle> triangles = box_triangles();
    REQUIRE(triangles.size() == 10);
    for (int i = 0; i < 10; ++i) {
        CAPTURE(i);
        CHECK(triangles[i].front == (i < 4));
    }
    // The ray cast's triangles in gl_PrimitiveID order are those of the index buffer.
    std::vector<GLuint> indices;
    for (GLuint f = 0; f < 5; ++f)
        for (const GLuint k : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(4 * f + k);
    CHECK(box_indices() == indices);
}

TEST_CASE("framebuffer_ops: scissor: the clear and the draw stay in their rectangles") {
    Lab lab;
    // Frames of several shapes: the scene is letterboxed to its 1:1 viewport.
    struct Shape {
        int width, height;
        glm::ivec4 viewport;
    };
    const Shape shapes[] = {{512, 512, {0, 0, 512, 512}},
                            {768, 512, {128, 0, 512, 512}},
                            {1024, 768, {128, 0, 768, 768}},
                            {384, 384, {0, 0, 384, 384}}};
    for (const Shape& s : shapes)
        for (const bool scissor : {true, false}) {
            CAPTURE(s.width);
            CAPTURE(s.height);
            CAPTURE(scissor);
            const fw::RenderOutput out = lab.render(
                {{"scene", "scissor"}, {"scissor", scissor ? "true" : "false"}}, s.width, s.height);
            PixelTally tally{"scissor", 1.0f / 255.0f};
            for (int y = 0; y < s.height; ++y)
                for (int x = 0; x < s.width; ++x)
                    tally.check(x, y, scissor_pixel(s.viewport, scissor, x, y),
                                rgb(out.color, x, y));
            tally.require(long(s.width) * s.height);
        }
    const fw::RenderOutput square = lab.render({{"scene", "scissor"}});
    const fw::RenderOutput wide = lab.render({{"scene", "scissor"}}, 768, 512);
    const glm::vec3 clear(kScissorClear), draw(kScissorDraw), black(0.0f);
    bool pass = true;
    pass = fw::test::probe_rgb(square.color, 100, 100, clear) && pass;
    pass = fw::test::probe_rgb(square.color, 300, 200, draw) && pass;
    pass = fw::test::probe_rgb(square.color, 400, 400, draw) && pass;
    pass = fw::test::probe_rgb(square.color, 100, 300, black) && pass;
    pass = fw::test::probe_rgb(square.color, 460, 100, black) && pass;
    pass = fw::test::probe_rgb(wide.color, 128 + 100, 100, clear) && pass;
    pass = fw::test::probe_rgb(wide.color, 50, 100, black) && pass;
    pass = fw::test::probe_rgb(wide.color, 128 + 400, 400, draw) && pass;
    CHECK(pass);
}

TEST_CASE("framebuffer_ops: each frame starts cleared, whatever state the last one left") {
    Lab lab;
    // scissor leaves the scissor test on; sorting, depth_write=false, depth writes off.
    lab.render({{"scene", "scissor"}});
    lab.render({{"scene", "sorting"}, {"depth_write", "false"}});
    GLboolean depth_mask = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask);
    CHECK(depth_mask == GL_FALSE);
    const fw::RenderOutput blend = lab.render({{"scene", "blend"}});
    const glm::vec3 background = stored(glm::vec3(kBlendBackground));
    const float tol = 2.0f / 255.0f;
    bool pass = true;
    pass = fw::test::probe_rgb(blend.color, pixel(-0.9f), pixel(0.9f), background, tol) && pass;
    for (const glm::ivec2 corner : {glm::ivec2(0, 0), glm::ivec2(kSize - 1, 0),
                                    glm::ivec2(0, kSize - 1), glm::ivec2(kSize - 1, kSize - 1)})
        pass = fw::test::probe_rgb(blend.color, corner.x, corner.y, background, tol) && pass;
    pass =
        fw::test::probe_rgb(blend.color, pixel(0.5f), pixel(0.5f), over(kQuadB, background), tol) &&
        pass;
    const fw::RenderOutput discard = lab.render({{"scene", "discard"}});
    pass = fw::test::probe_depth(discard.depth, 20, 20, 1.0f) && pass;
    pass = fw::test::probe_depth(discard.depth, kSize - 20, kSize - 20, 1.0f) && pass;
    // The scissor rectangle left on: the next clear still reaches every
    // pixel, where scene stencil leaves the frame black: in kClearRect,
    // outside the outline.
    lab.render({{"scene", "scissor"}});
    CHECK(glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE);
    const fw::RenderOutput stencil = lab.render({{"scene", "stencil"}});
    pass = fw::test::probe_rgb(stencil.color, 100, 100, glm::vec3(0.0f)) && pass;
    pass = fw::test::probe_rgb(stencil.color, 300, 80, glm::vec3(0.0f)) && pass;
    // A frame of the lab that ends with depth writes off (sorting,
    // depth_write=false) writes no depth, so the clear after it has nothing
    // to undo. Here the lab's draw runs, without a frame and a clear of its
    // own, right after a frame that left the fence's depth 0.25, and leaves
    // depth writes off: the next clear must still reset the depth, or the
    // back quad fails the depth test in the fence's holes.
    lab.render({{"scene", "discard"}, {"alpha_test", "false"}});
    lab.renderer.lab().draw(lab.params({{"scene", "sorting"}, {"depth_write", "false"}}),
                            fw::Frame{});
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask);
    CHECK(depth_mask == GL_FALSE);
    const fw::DepthImage before = lab.renderer.framebuffer()->read_depth();
    pass = fw::test::probe_depth(before, 204, 204, 0.25f) && pass;
    const fw::RenderOutput holes = lab.render({{"scene", "discard"}});
    pass = fw::test::probe_rgb(holes.color, 204, 204, glm::vec3(kBackColor), tol) && pass;
    pass = fw::test::probe_depth(holes.depth, 204, 204, 0.75f) && pass;
    CHECK(pass);
}
