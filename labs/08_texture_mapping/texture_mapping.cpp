// Lab 8 `texture-mapping`: textures, their coordinates and how they are read.
//
// Teaches: texture coordinates set per vertex or computed by a planar,
// cylindrical or spherical mapping; perspective-correct against affine
// lookups; wrap modes outside [0, 1]; magnification and minification
// filters, mipmaps and the level of detail; a light map modulating a base
// texture; a texture as the diffuse colour of a lit surface; an image file
// read into a texture, bottom row first.
// Lecture: texture mapping, (s, t) coordinates set by hand or computed, the
// perspective-correct interpolation of texture coordinates, lookups on a
// fragment-to-fragment basis, light maps.
// GL: glActiveTexture, glBindTexture, glTexParameteri, glTexParameterfv,
// glGenerateMipmap, the sampler uniforms (sampler2D, texture()), glViewport,
// glEnable(GL_DEPTH_TEST), glDepthFunc, glBindVertexArray with glDrawElements
// (every mesh); stb_image's stbi_load for the image file.
// Student parts (marked TODO): bind_texture(), set_wrap(), set_filters(),
// build_mipmaps() and bind_maps() in sampler_state.cpp; planar(), cylindrical(), spherical() and
// level_of_detail() in mappings.cpp; the file's row order in load_image()
// (textures.cpp); the mappings and the lighting in
// shaders/08_texture_mapping/sphere.frag and the modulation in quad.frag.
#include <string>

#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "mappings.hpp"
#include "parameters.hpp"
#include "sampler_state.hpp"
#include "scenes.hpp"
#include "textures.hpp"
// A_POSITION, A_UV, A_NORMAL (attribute locations), shared with the shaders.
#include "shared.glsl"

namespace texture_mapping {

namespace {

constexpr const char* kMvpUniform = "u_mvp";          // textured.vert
constexpr const char* kTextureUniform = "u_texture";  // every fragment shader
constexpr const char* kMappingUniform = "u_mapping";  // sphere.frag
constexpr const char* kLitUniform = "u_lit";
constexpr const char* kLightUniform = "u_light";
constexpr const char* kKaUniform = "u_ka";
constexpr const char* kKdUniform = "u_kd";
constexpr const char* kAffineUniform = "u_affine";  // plane.frag
constexpr const char* kMapsUniform = "u_maps";      // quad.frag

// A mesh in a vertex buffer, an index buffer and the vertex array reading both.
struct GpuMesh {
    fw::Buffer vbo, ibo;
    fw::VertexArray vao;
};

GpuMesh upload(const Mesh& mesh, const std::string& label) {
    GpuMesh g;
    g.vbo = fw::Buffer::from(mesh.vertices, GL_ARRAY_BUFFER, label + " vertices");
    g.ibo = fw::Buffer::from(mesh.indices, GL_ELEMENT_ARRAY_BUFFER, label + " indices");
    g.vao = fw::VertexArray(fw::VertexArrayDesc{.vertices = &g.vbo,
                                                .layout = fw::VertexLayout::of<Vertex>()
                                                              .attr(A_POSITION, &Vertex::position)
                                                              .attr(A_UV, &Vertex::uv)
                                                              .attr(A_NORMAL, &Vertex::normal),
                                                .indices = &g.ibo,
                                                .index_type = GL_UNSIGNED_INT,
                                                .label = label});
    return g;
}

void draw_mesh(const GpuMesh& mesh) {
    glBindVertexArray(mesh.vao.id());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.vao.index_count()), GL_UNSIGNED_INT,
                   nullptr);
}

// A texture of `image`, read texel by texel (GL_NEAREST) until the lab sets
// other filters, with `levels` storage levels (1: no mipmaps).
fw::Texture2D texture_of(const fw::Image& image, const std::string& label, int levels = 1) {
    fw::Texture2DDesc desc;
    desc.width = image.width;
    desc.height = image.height;
    desc.data = image.pixels.data();
    desc.min_filter = GL_NEAREST;
    desc.mag_filter = GL_NEAREST;
    desc.levels = levels;
    desc.label = label;
    return fw::Texture2D(desc);
}

}  // namespace

class TextureMappingLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        fw::LabInfo i;
        i.title = "Texture mapping";
        i.aspect = 1.0;  // a square scene: letterboxed in a frame of another shape
        i.params = params();
        i.functions = {fw::unit_function("planar", &planar),
                       fw::unit_function("cylindrical", &cylindrical),
                       fw::unit_function("spherical", &spherical),
                       fw::unit_function("level_of_detail", &level_of_detail)};
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        // File names within shaders/08_texture_mapping/.
        sphere_program_ = &programs.load({"textured.vert", "sphere.frag"});
        plane_program_ = &programs.load({"textured.vert", "plane.frag"});
        quad_program_ = &programs.load({"textured.vert", "quad.frag"});
        sphere_ = upload(sphere(), "icosphere");
        floor_ = upload(floor_plane(), "floor");
        wrap_quad_ = upload(wrap_quad(), "wrap quad");
        magnify_quad_ = upload(magnify_quad(), "magnify quad");
        minify_quad_ = upload(minify_quad(), "minify quad");
        lightmap_quad_ = upload(lightmap_quad(), "lightmap quad");

        checker_ = texture_of(sphere_checker(), "sphere checker");
        // The one texture read from a file, next to the lab's shaders.
        image_ = texture_of(load_image(fw::shader_path(FW_LAB_DIR "/grid.png")), "grid.png");
        floor_texture_ = texture_of(floor_checker(), "floor checker");
        ramp_ = texture_of(ramp(), "ramp");
        // Storage for the whole chain, 256 x 256 down to 1 x 1, and the
        // levels below 0 made from level 0 once, after it is uploaded.
        fine_ = texture_of(fine_checker(), "fine checker", 9);
        build_mipmaps(fine_);
        base_ = texture_of(base_texture(), "base");
        light_map_ = texture_of(light_map(), "light map");
    }

    void draw(const fw::ParamValues& p, const fw::Frame&) override {
        glDisable(GL_CULL_FACE);
        glDisable(GL_DEPTH_TEST);
        switch (p[kScene]) {
            case Scene::Coordinates:
                draw_sphere(p);
                break;
            case Scene::Perspective:
                draw_floor();
                break;
            case Scene::Wrap:
                draw_quad(wrap_quad_, ramp_, p[kWrap], MinFilter::Nearest, MagFilter::Nearest);
                break;
            case Scene::Magnify:
                draw_quad(magnify_quad_, ramp_, Wrap::ClampToEdge, MinFilter::Nearest,
                          p[kMagFilter]);
                break;
            case Scene::Minify:
                draw_quad(minify_quad_, fine_, Wrap::Repeat, p[kMinFilter], MagFilter::Nearest);
                break;
            case Scene::Lightmap:
                draw_lightmap(p);
                break;
        }
    }

private:
    void draw_sphere(const fw::ParamValues& p) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        bind_texture(0, p[kImage] ? image_ : checker_);
        set_wrap(Wrap::Repeat);
        set_filters(MinFilter::Nearest, MagFilter::Nearest);
        sphere_program_->use();
        sphere_program_->set(kTextureUniform, 0);
        sphere_program_->set(kMvpUniform, sphere_view_projection());
        sphere_program_->set(kMappingUniform, static_cast<int>(p[kMapping]));
        sphere_program_->set(kLitUniform, p[kLit]);
        // The light matters only once the student's lighting is written.
        sphere_program_->set_if_active(kLightUniform, kLightDirection);
        sphere_program_->set_if_active(kKaUniform, kKa);
        sphere_program_->set_if_active(kKdUniform, kKd);
        draw_mesh(sphere_);
    }

    // The same floor twice: perspective-correct coordinates in the left half
    // of the viewport, affine ones in the right half.
    void draw_floor() {
        GLint v[4];
        glGetIntegerv(GL_VIEWPORT, v);
        bind_texture(0, floor_texture_);
        set_wrap(Wrap::Repeat);
        set_filters(MinFilter::Nearest, MagFilter::Nearest);
        plane_program_->use();
        plane_program_->set(kTextureUniform, 0);
        plane_program_->set(kMvpUniform, floor_view_projection());
        for (const bool affine : {false, true}) {
            glViewport(v[0] + (affine ? v[2] / 2 : 0), v[1], v[2] / 2, v[3]);
            // Unused, and dropped, until the student's lookup is written.
            plane_program_->set_if_active(kAffineUniform, affine);
            draw_mesh(floor_);
        }
        glViewport(v[0], v[1], v[2], v[3]);
    }

    void draw_quad(const GpuMesh& quad, const fw::Texture2D& texture, Wrap wrap, MinFilter min,
                   MagFilter mag) {
        bind_texture(0, texture);
        set_wrap(wrap);
        set_filters(min, mag);
        quad_program_->use();
        quad_program_->set(kTextureUniform, 0);
        quad_program_->set(kMvpUniform, glm::mat4(1.0f));
        quad_program_->set(kMapsUniform, MAPS_BASE);
        draw_mesh(quad);
    }

    void draw_lightmap(const fw::ParamValues& p) {
        quad_program_->use();
        bind_maps(*quad_program_, base_, light_map_);
        for (const GLuint unit : {0u, 1u}) {
            glActiveTexture(GL_TEXTURE0 + unit);
            set_wrap(Wrap::ClampToEdge);
            set_filters(MinFilter::Nearest, MagFilter::Nearest);
        }
        quad_program_->set(kMvpUniform, glm::mat4(1.0f));
        quad_program_->set(kMapsUniform, static_cast<int>(p[kMaps]));
        draw_mesh(lightmap_quad_);
    }

    fw::Program* sphere_program_ = nullptr;
    fw::Program* plane_program_ = nullptr;
    fw::Program* quad_program_ = nullptr;
    GpuMesh sphere_, floor_, wrap_quad_, magnify_quad_, minify_quad_, lightmap_quad_;
    fw::Texture2D checker_, image_, floor_texture_, ramp_, fine_, base_, light_map_;
};

FW_LAB(TextureMappingLab)

}  // namespace texture_mapping
