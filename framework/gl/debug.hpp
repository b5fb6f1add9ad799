// GL errors that say where and why: KHR_debug messages (core since GL 4.3)
// plus glGetError, with the labels of the objects that were bound at the
// time, because "GL_INVALID_OPERATION" alone never tells a student which draw
// or which program was at fault.
#pragma once

#include <glad/gl.h>
#include <glad/gl_names.h>

#include <string>
#include <vector>

namespace fw {

// Installs a synchronous debug callback (GL_DEBUG_OUTPUT_SYNCHRONOUS, so a
// message arrives inside the call that caused it). Messages of type ERROR,
// and any of HIGH severity, are kept in a per-thread list until check_gl()
// reports them. Call once after the context is current.
void enable_debug_output();

// Throws fw::Error if GL recorded an error since the last check: every
// pending glGetError code, the collected debug messages, and the labels of
// the bound program, vertex array and draw framebuffer, e.g.
//   GL error after draw in lab pipeline: GL_INVALID_OPERATION: <message>
//   [program '00_pipeline/pipeline.vert + pipeline.frag', vertex array 'quads',
//    framebuffer 'offscreen 512x512']
// `where` says what was just done ("draw in lab pipeline").
void check_gl(const char* where);
inline void check_gl(const std::string& where) { check_gl(where.c_str()); }

// Removes and returns the debug messages collected so far (for tests and the
// window's error panel). check_gl() consumes them as well.
std::vector<std::string> take_debug_messages();

// glObjectLabel / glGetObjectLabel. `identifier` is GL_BUFFER, GL_PROGRAM,
// GL_VERTEX_ARRAY, GL_TEXTURE, GL_FRAMEBUFFER, GL_QUERY, GL_SHADER...
// Labels longer than GL_MAX_LABEL_LENGTH are cut to fit.
void set_object_label(GLenum identifier, GLuint id, const std::string& label);
std::string object_label(GLenum identifier, GLuint id);

// GL's name of `value` among the names of `group`, one of the groups of the
// Khronos registry (gl.xml) that glad reads: GLAD_GL_GROUP_PrimitiveType
// names 0 GL_POINTS, GLAD_GL_GROUP_BlendingFactor GL_ZERO. The default,
// GLAD_GL_GROUP_any, takes any name of the value. One table names every enum
// of the loader's API, generated with it (scripts/gen-gl-names.py); "0x1234"
// for a value it does not name.
std::string gl_enum_name(GLenum value, GladGlGroup group = GLAD_GL_GROUP_any);
// The same name, or null where the table names no such value in `group`.
const char* gl_enum_name_or_null(GLenum value, GladGlGroup group);

}  // namespace fw
