#include "tests/framework/record_scene.hpp"

#include "framework/gl/debug.hpp"

namespace record_test {

namespace {

const char* kVertex = R"(#version 430 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec2 a_unused;  // read by nothing: optimised out
void main() { gl_Position = vec4(a_position, 1.0); gl_ClipDistance[0] = a_position.x; }
)";

const char* kFragment = R"(#version 430 core
uniform vec4 u_color;
uniform float u_unused;  // declared, never read: not active
uniform sampler2D u_texture;
out vec4 color;
void main() { color = u_color * texture(u_texture, gl_FragCoord.xy / 64.0); }
)";

}  // namespace

Scene::Scene() {
    std::vector<fw::Shader> shaders;
    shaders.push_back(fw::Shader::from_source(fw::Stage::Vertex, kVertex, "record/scene.vert"));
    shaders.push_back(fw::Shader::from_source(fw::Stage::Fragment, kFragment, "record/scene.frag"));
    program = fw::Program::from_shaders(std::move(shaders));
    program.set("u_color", glm::vec4(1.0f, 0.5f, 0.25f, 0.5f));
    program.set("u_texture", 0);
    const float triangle[] = {-1, -1, 0, 1, -1, 0, 0, 1, 0};
    glGenBuffers(1, &vbo);  // unlabelled: named by creation order
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof triangle, triangle, GL_STATIC_DRAW);
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    fw::set_object_label(GL_VERTEX_ARRAY, vao, "triangle");
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    glEnableVertexAttribArray(0);
    glBindVertexArray(0);
    const unsigned char texel[4] = {255, 255, 255, 255};
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    fw::set_object_label(GL_TEXTURE, texture, "white");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
}

Scene::~Scene() {
    glDeleteTextures(1, &texture);
    glDeleteVertexArrays(1, &vao);
    glDeleteBuffers(1, &vbo);
    fw::gl_calls::observe(saved);
}

void Scene::reset() {
    for (GLenum cap : {GL_BLEND, GL_DEPTH_TEST, GL_STENCIL_TEST, GL_SCISSOR_TEST, GL_CULL_FACE,
                       GL_RASTERIZER_DISCARD, GL_CLIP_DISTANCE0})
        glDisable(cap);
    glBlendFunc(GL_ONE, GL_ZERO);
    glBlendEquation(GL_FUNC_ADD);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glViewport(0, 0, 64, 64);
    glScissor(0, 0, 64, 64);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    program.set("u_color", glm::vec4(1.0f, 0.5f, 0.25f, 0.5f));
}

void Scene::draw() {
    program.use();
    glBindVertexArray(vao);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

}  // namespace record_test
