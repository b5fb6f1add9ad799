// Lab 9's uniform block: the std140 placement of one member and the packing
// of SceneBlock (student parts). What the block scene draws and reports
// with them is in block_scene.cpp.
#include "block.hpp"

namespace buffers {

Std140Place std140_place(int offset, GlslType type) {
    // BEGIN SOLUTION
    // STUDENT: (void)type;  // TODO: the type's base alignment and size (block.hpp)
    // STUDENT: return {offset, offset + 4};
    int alignment = 16, size = 16;
    switch (type) {
        case GlslType::Float:
            alignment = size = 4;
            break;
        case GlslType::Vec2:
            alignment = size = 8;
            break;
        case GlslType::Vec3:
            size = 12;
            break;
        case GlslType::Vec4:
            break;
        case GlslType::Mat3:
            size = 3 * 16;
            break;
        case GlslType::Mat4:
            size = 4 * 16;
            break;
    }
    const int start = (offset + alignment - 1) / alignment * alignment;
    return {start, start + size};
    // END SOLUTION
}

std::vector<int> std140_offsets(const std::vector<GlslType>& members) {
    std::vector<int> out;
    int end = 0;
    for (GlslType type : members) {
        const Std140Place place = std140_place(end, type);
        out.push_back(place.offset);
        end = place.end;
    }
    out.push_back((end + 15) / 16 * 16);
    return out;
}

const std::vector<GlslType>& scene_block_members() {
    static const std::vector<GlslType> members = {GlslType::Mat4, GlslType::Mat3, GlslType::Vec3,
                                                  GlslType::Float, GlslType::Vec4};
    return members;
}

SceneBlock pack_scene(const glm::mat4& mvp, const glm::mat3& normal_matrix, glm::vec3 light,
                      float ambient, glm::vec4 color) {
    SceneBlock block{};
    block.mvp = mvp;
    // BEGIN SOLUTION
    // STUDENT: (void)normal_matrix, (void)light, (void)ambient, (void)color;
    // STUDENT: // TODO: the normal matrix's three columns, the light, ambient and colour
    for (int c = 0; c < 3; ++c) block.normal_matrix[c] = glm::vec4(normal_matrix[c], 0.0f);
    block.light = light;
    block.ambient = ambient;
    block.color = color;
    // END SOLUTION
    return block;
}

}  // namespace buffers
