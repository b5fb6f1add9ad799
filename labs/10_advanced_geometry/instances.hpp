// Lab 10's grid of instances: one quad in buffers, each instance's colour in
// a buffer of its own, and the one instanced draw (draw_instances, a student
// part, in instances.cpp). Where each instance goes is grid.vert's part.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "framework/gl.hpp"

namespace advanced_geometry {

// The quad (corners (+-1, +-1), two triangles by six indices), a buffer of
// up to kMaxCells^2 instance colours (one vec3 each, tightly packed), and
// the vertex array that reads the corners at A_POSITION. The colours are
// not yet an attribute: draw_instances() makes them one.
struct InstanceGrid {
    fw::Buffer corners, indices, colors;
    fw::VertexArray vertices;
};
InstanceGrid make_instance_grid();

// The sheet's colour of each instance of a columns x rows grid: instance
// i = column + columns row has ((column + 1) / columns, (row + 1) / rows, 0.3).
std::vector<glm::vec3> instance_colors(int columns, int rows);

// Draws `count` instances of the quad with one call, instance i's colour
// being element i of grid.colors (attribute A_COLOR, advancing once per
// instance).
void draw_instances(const InstanceGrid& grid, int count);

}  // namespace advanced_geometry
