// Lab 13 `surface-detail`: bump mapping, environment mapping and a ray caster.
//
// Teaches: a height map turned into a normal map by central differences, the
// tangent frame of each vertex from the mesh's UVs (T, B, N by Gram-Schmidt)
// and lighting in tangent space, beside the interpolated normal alone; a cube
// map's six faces in GL's order, reflect() and refract() into it and Schlick's
// Fresnel term mixing the two; a ray caster on the CPU (rays through pixel
// centres, ray-triangle tests, the nearest hit, shadow rays to each light)
// compared pixel for pixel with GL's z-buffer image of the same scene.
// Lecture: texturing methods (bump mapping: the smooth surface's normal
// distorted; environment or reflection maps: "ray-tracing like output");
// incremental rendering against ray tracing, image precision, the cost
// #pixels x #objects x (#lights + 1), shadows cast by objects on each other.
// GL: glTexSubImage2D with GL_TEXTURE_CUBE_MAP_POSITIVE_X + face,
// glPixelStorei, glBindVertexArray with glDrawArrays, glEnable(GL_DEPTH_TEST),
// glDepthFunc, glClear, glViewport; GLSL's samplerCube, reflect(), refract(),
// gl_PrimitiveID.
// Student parts (marked TODO): normal_map() and tangent_frame() in
// surface_math.cpp; the light in tangent space in
// shaders/13_surface_detail/bump.vert; upload_cube_faces() in
// environment.cpp; reflection, refraction and Fresnel in envmap.frag;
// pixel_direction(), intersect_triangle(), nearest_hit() and in_shadow() in
// raycast.cpp.
#include <vector>

#include "compare.hpp"
#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "parameters.hpp"
#include "raycast_image.hpp"
#include "scenes.hpp"
// A_*, NORMALS_*, ENV_*, OUTPUT_*, VIEW_*: shared with the shaders.
#include "shared.glsl"

namespace surface_detail {

namespace {

constexpr const char* kProjectionUniform = "u_projection";  // bump.vert
constexpr const char* kLightUniform = "u_light";
constexpr const char* kNormalMapUniform = "u_normal_map";  // bump.frag
constexpr const char* kNormalsUniform = "u_normals";
constexpr const char* kEnvUniform = "u_env";  // envmap.frag
constexpr const char* kEnvModeUniform = "u_env_mode";
constexpr const char* kIorUniform = "u_ior";
constexpr const char* kRadiusUniform = "u_radius";
constexpr const char* kViewProjectionUniform = "u_view_projection";  // flat.vert
constexpr const char* kLight0Uniform = "u_light0";                   // flat.frag
constexpr const char* kLight1Uniform = "u_light1";
constexpr const char* kLightCountUniform = "u_light_count";
constexpr const char* kOutputUniform = "u_output";
constexpr const char* kCpuUniform = "u_cpu";  // show.frag
constexpr const char* kGlUniform = "u_gl";
constexpr const char* kViewUniform = "u_view";

// scene=raycast: a triangle's corner for GL, with the triangle's normal and colour.
struct FlatVertex {
    glm::vec3 position, normal, color;
};

std::vector<FlatVertex> flat_vertices(const std::vector<Triangle>& scene) {
    std::vector<FlatVertex> out;
    for (const Triangle& t : scene)
        for (const glm::vec3& p : {t.a, t.b, t.c}) out.push_back({p, t.normal(), t.color});
    return out;
}

fw::Texture2D nearest_texture(int size, GLenum format, const std::string& label) {
    fw::Texture2DDesc desc;
    desc.width = desc.height = size;
    desc.internal_format = format;
    desc.min_filter = desc.mag_filter = GL_NEAREST;
    desc.wrap = GL_REPEAT;
    desc.label = label;
    return fw::Texture2D(desc);
}

}  // namespace

class SurfaceDetailLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        fw::LabInfo i;
        i.title = "Surface detail: bump maps, environment maps, ray casting";
        i.aspect = 1.0;  // a square scene: letterboxed in a frame of another shape
        i.params = params();
        i.functions = {fw::unit_function("normal_map", &height_normal),
                       fw::unit_function("tangent_frame", &tangent_frame),
                       fw::unit_function("pixel_direction", &pixel_direction),
                       fw::unit_function("intersect_triangle", &intersect_triangle)};
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        // File names within shaders/13_surface_detail/.
        bump_ = &programs.load({"bump.vert", "bump.frag"});
        env_ = &programs.load({"screen.vert", "envmap.frag"});
        flat_ = &programs.load({"flat.vert", "flat.frag"});
        show_ = &programs.load({"screen.vert", "show.frag"});
        squares_vbo_ = fw::Buffer::from(bump_squares(), GL_ARRAY_BUFFER, "squares vertices");
        squares_ = fw::VertexArray(
            fw::VertexArrayDesc{.vertices = &squares_vbo_,
                                .layout = fw::VertexLayout::of<BumpVertex>()
                                              .attr(A_POSITION, &BumpVertex::position)
                                              .attr(A_NORMAL, &BumpVertex::normal)
                                              .attr(A_TANGENT, &BumpVertex::tangent)
                                              .attr(A_BITANGENT, &BumpVertex::bitangent)
                                              .attr(A_UV, &BumpVertex::uv),
                                .label = "squares"});
        heights_ = height_map();
        normal_tex_ = nearest_texture(heights_.size, GL_RGBA32F, "normal map");
        cube_ = fw::TextureCube({kFaceSize, GL_RGBA8, GL_NEAREST, GL_NEAREST, "environment"});
        upload_cube_faces(cube_, cube_faces());
        scene_ = ray_scene();
        scene_vbo_ = fw::Buffer::from(flat_vertices(scene_), GL_ARRAY_BUFFER, "scene vertices");
        scene_vao_ = fw::VertexArray(
            fw::VertexArrayDesc{.vertices = &scene_vbo_,
                                .layout = fw::VertexLayout::of<FlatVertex>()
                                              .attr(A_POSITION, &FlatVertex::position)
                                              .attr(A_NORMAL, &FlatVertex::normal)
                                              .attr(A_COLOR, &FlatVertex::color),
                                .label = "ray scene"});
        gl_fb_ = fw::Framebuffer({kCast, kCast, "GL's image"});
        cpu_tex_ = nearest_texture(kCast, GL_RGBA8, "ray-cast image");
        screen_ = fw::VertexArray::blank("viewport triangle");
    }

    void draw(const fw::ParamValues& p, const fw::Frame&) override {
        glDisable(GL_DEPTH_TEST);
        switch (p[kScene]) {
            case Scene::Bump:
                draw_bump(p);
                break;
            case Scene::Envmap:
                draw_envmap(p);
                break;
            case Scene::Raycast:
                draw_raycast(p);
                break;
        }
        glBindVertexArray(0);
    }

    // README.md, Stats (scene raycast only).
    nlohmann::json stats(const fw::ParamValues& p, const fw::Frame&) const override {
        if (p[kScene] != Scene::Raycast) return nlohmann::json::object();
        return compare_stats(cast_, gl_image_, gl_ids_, scene_, static_cast<int>(p[kLightsParam]));
    }

private:
    void draw_bump(const fw::ParamValues& p) {
        const std::vector<glm::vec3> normals = normal_map(heights_, p[kBumpScale]);
        normal_tex_.update(normals.data(), GL_RGB, GL_FLOAT);
        bump_->use();
        bump_->set(kProjectionUniform, bump_projection());
        bump_->set(kLightUniform, kBumpLight);
        bump_->set(kNormalsUniform, static_cast<int>(p[kNormalsParam]));
        normal_tex_.bind(0);
        bump_->set(kNormalMapUniform, 0);
        glBindVertexArray(squares_.id());
        glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(squares_.vertex_count()));
    }

    void draw_envmap(const fw::ParamValues& p) {
        env_->use();
        cube_.bind(0);
        // Unused, and dropped, until the student's lookups are written.
        env_->set_if_active(kEnvUniform, 0);
        env_->set_if_active(kIorUniform, p[kIor]);
        env_->set(kEnvModeUniform, static_cast<int>(p[kEnv]));
        env_->set(kRadiusUniform, kSphereRadius);
        glBindVertexArray(screen_.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    // The ray caster's image, then GL's (colour, then each pixel's triangle)
    // in a 64 x 64 framebuffer with the depth test, then both shown.
    void draw_raycast(const fw::ParamValues& p) {
        GLint frame = 0, viewport[4] = {0, 0, 0, 0};
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &frame);
        glGetIntegerv(GL_VIEWPORT, viewport);
        const int lights = static_cast<int>(p[kLightsParam]);
        cast_ = cast_scene(scene_, lights);
        cpu_tex_.update(cast_.color.pixels.data());

        gl_fb_.bind();
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        flat_->use();
        flat_->set(kViewProjectionUniform, ray_view_projection());
        flat_->set(kLight0Uniform, kRayLights[0]);
        flat_->set(kLight1Uniform, kRayLights[1]);
        flat_->set(kLightCountUniform, lights);
        glBindVertexArray(scene_vao_.id());
        for (const int output : {OUTPUT_ID, OUTPUT_COLOR}) {
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            flat_->set(kOutputUniform, output);
            glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(scene_vao_.vertex_count()));
            (output == OUTPUT_ID ? gl_ids_ : gl_image_) = gl_fb_.read_color();
        }
        glDisable(GL_DEPTH_TEST);

        glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(frame));
        show_->use();
        cpu_tex_.bind(0);
        gl_fb_.color_texture().bind(1);
        show_->set(kCpuUniform, 0);
        show_->set(kGlUniform, 1);
        glBindVertexArray(screen_.id());
        const int x = viewport[0], y = viewport[1], w = viewport[2], h = viewport[3];
        if (p[kView] == View::Split) {
            show(VIEW_CPU, x, y + h / 4, w / 2, h / 2);
            show(VIEW_GL, x + w / 2, y + h / 4, w / 2, h / 2);
        } else {
            const View v = p[kView];
            show(v == View::Cpu ? VIEW_CPU : v == View::Gl ? VIEW_GL : VIEW_DIFFERENCE, x, y, w, h);
        }
        glViewport(x, y, w, h);
    }

    void show(int view, int x, int y, int w, int h) {
        glViewport(x, y, w, h);
        show_->set(kViewUniform, view);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    fw::Program* bump_ = nullptr;
    fw::Program* env_ = nullptr;
    fw::Program* flat_ = nullptr;
    fw::Program* show_ = nullptr;
    fw::Buffer squares_vbo_, scene_vbo_;
    fw::VertexArray squares_, scene_vao_, screen_;
    HeightMap heights_;
    fw::Texture2D normal_tex_, cpu_tex_;
    fw::TextureCube cube_;
    std::vector<Triangle> scene_;
    fw::Framebuffer gl_fb_;
    CastImage cast_;
    fw::Image gl_image_, gl_ids_;
};

FW_LAB(SurfaceDetailLab)

}  // namespace surface_detail
