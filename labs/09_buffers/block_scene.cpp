// Lab 9's block scene, with the student parts of block.cpp: its surface,
// and SceneBlock's layout three ways for the frame's stats.
#include <cstddef>
#include <nlohmann/json.hpp>

#include "block.hpp"
#include "framework/meshes.hpp"
// A_POSITION, A_NORMAL: the attribute locations, shared with the shaders.
#include "shared.glsl"

namespace buffers {

nlohmann::json block_layouts(const fw::Program& program) {
    const GLuint id = program.id();
    const char* names[] = {"mvp", "normal_matrix", "light", "ambient", "color"};
    GLuint indices[5];
    GLint offsets[5];
    glGetUniformIndices(id, 5, names, indices);
    glGetActiveUniformsiv(id, 5, indices, GL_UNIFORM_OFFSET, offsets);
    GLint size = 0;
    glGetActiveUniformBlockiv(id, glGetUniformBlockIndex(id, "SceneBlock"),
                              GL_UNIFORM_BLOCK_DATA_SIZE, &size);
    std::vector<int> driver(offsets, offsets + 5);
    driver.push_back(size);
    const std::vector<int> cpp = {
        int(offsetof(SceneBlock, mvp)),   int(offsetof(SceneBlock, normal_matrix)),
        int(offsetof(SceneBlock, light)), int(offsetof(SceneBlock, ambient)),
        int(offsetof(SceneBlock, color)), int(sizeof(SceneBlock))};
    return {{"driver", driver},
            {"struct", cpp},
            {"std140_place", std140_offsets(scene_block_members())}};
}

namespace {

// A vertex of the ellipsoid's mesh.
struct SurfaceVertex {
    glm::vec3 position;
    glm::vec3 normal;
};

}  // namespace

Ellipsoid make_ellipsoid() {
    const fw::MeshData mesh = fw::icosphere(3);
    std::vector<SurfaceVertex> v;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        v.push_back({mesh.positions[i], mesh.normals[i]});
    Ellipsoid e;
    e.vbo = fw::Buffer::from(v, GL_ARRAY_BUFFER, "ellipsoid vertices");
    e.ibo = fw::Buffer::from(mesh.indices, GL_ELEMENT_ARRAY_BUFFER, "ellipsoid indices");
    e.vertices = fw::VertexArray(
        fw::VertexArrayDesc{.vertices = &e.vbo,
                            .layout = fw::VertexLayout::of<SurfaceVertex>()
                                          .attr(A_POSITION, &SurfaceVertex::position)
                                          .attr(A_NORMAL, &SurfaceVertex::normal),
                            .indices = &e.ibo,
                            .index_type = GL_UNSIGNED_INT,
                            .label = "ellipsoid"});
    fw::BufferDesc block;
    block.target = GL_UNIFORM_BUFFER;
    block.usage = GL_DYNAMIC_DRAW;
    block.size = sizeof(SceneBlock);
    block.label = "SceneBlock";
    e.block = fw::Buffer(block);
    return e;
}

}  // namespace buffers
