// Lab 10's grid of instances (instances.hpp); the student part is
// draw_instances().
#include "instances.hpp"

#include <cstdint>

#include "parameters.hpp"
// A_POSITION, A_COLOR: the attribute locations, shared with the shaders.
#include "shared.glsl"

namespace advanced_geometry {

InstanceGrid make_instance_grid() {
    InstanceGrid g;
    const std::vector<glm::vec2> corners = {{-1, -1}, {1, -1}, {-1, 1}, {1, 1}};
    const std::vector<std::uint32_t> indices = {0, 1, 2, 2, 1, 3};
    g.corners = fw::Buffer::from(corners, GL_ARRAY_BUFFER, "quad corners");
    g.indices = fw::Buffer::from(indices, GL_ELEMENT_ARRAY_BUFFER, "quad indices");
    fw::BufferDesc desc;
    desc.size = kMaxCells * kMaxCells * sizeof(glm::vec3);
    desc.usage = GL_DYNAMIC_DRAW;
    desc.label = "instance colours";
    g.colors = fw::Buffer(desc);
    fw::VertexLayout layout(sizeof(glm::vec2));
    layout.add({A_POSITION, 2, GL_FLOAT, 0, false, false});
    g.vertices = fw::VertexArray(fw::VertexArrayDesc{
        .vertices = &g.corners, .layout = layout, .indices = &g.indices, .label = "quad"});
    return g;
}

std::vector<glm::vec3> instance_colors(int columns, int rows) {
    std::vector<glm::vec3> out;
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column)
            out.emplace_back(float(column + 1) / float(columns), float(row + 1) / float(rows),
                             0.3f);
    return out;
}

void draw_instances(const InstanceGrid& grid, int count) {
    // The colours are one more attribute of the vertex array, read from
    // their own buffer; a divisor of 1 moves to the next colour once per
    // instance instead of once per vertex. Then one draw makes every
    // instance, each with its own gl_InstanceID.
    // BEGIN SOLUTION
    // STUDENT: (void)count;  // TODO: A_COLOR from grid.colors: glBindBuffer,
    // STUDENT: // glVertexAttribPointer, glEnableVertexAttribArray, glVertexAttribDivisor;
    // STUDENT: // then one glDrawElementsInstanced of `count` quads
    // STUDENT: glBindVertexArray(grid.vertices.id());
    // STUDENT: glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(grid.vertices.id());
    glBindBuffer(GL_ARRAY_BUFFER, grid.colors.id());
    glVertexAttribPointer(A_COLOR, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glEnableVertexAttribArray(A_COLOR);
    glVertexAttribDivisor(A_COLOR, 1);
    glDrawElementsInstanced(GL_TRIANGLES, 6, GL_UNSIGNED_INT, nullptr, count);
    // END SOLUTION
}

}  // namespace advanced_geometry
