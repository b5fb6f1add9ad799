// The whole GL wrapper: one RAII type per GL object, each with id() for raw
// GL calls. See framework/gl/*.hpp for each.
#pragma once

#include <glad/gl.h>

#include "framework/gl/buffer.hpp"
#include "framework/gl/cube_map.hpp"
#include "framework/gl/debug.hpp"
#include "framework/gl/framebuffer.hpp"
#include "framework/gl/program.hpp"
#include "framework/gl/query.hpp"
#include "framework/gl/shader.hpp"
#include "framework/gl/texture.hpp"
#include "framework/gl/transform_feedback.hpp"
#include "framework/gl/vertex_array.hpp"
