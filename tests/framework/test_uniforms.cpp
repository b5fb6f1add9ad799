// Program::set: every uniform error of docs/contract.md, Exit status and
// errors (unknown, optimised out, wrong type, wrong size), and the values
// that do arrive, read back with glGetUniform or by rendering.
#include <glad/gl.h>

#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/gl.hpp"
#include "tests/support/test_support.hpp"

namespace {

using fw::test::check_mentions;

std::string error_of(const std::function<void()>& f) { return fw::test::thrown(f); }

fw::Program uniforms_program() {
    return fw::Program::from_files({"tests/uniforms.vert", "tests/uniforms.frag"});
}

float uniform_float(const fw::Program& p, const char* name) {
    float v = -999.0f;
    glGetUniformfv(p.id(), glGetUniformLocation(p.id(), name), &v);
    return v;
}

int uniform_int(const fw::Program& p, const char* name) {
    int v = -999;
    glGetUniformiv(p.id(), glGetUniformLocation(p.id(), name), &v);
    return v;
}

}  // namespace

TEST_CASE("uniforms: the active uniforms are listed with their GLSL types") {
    fw::Program p = uniforms_program();
    const std::string list = p.describe_uniforms();
    check_mentions(list, {"u_color: vec3", "u_mvp: mat4", "u_weights[0]: float[4]",
                          "u_lights[0]: vec3[3]", "u_flag: bool", "u_count: int", "u_mask: uint",
                          "u_tint: mat3", "u_texture: sampler2D"});
    CHECK(list.find("u_unused") == std::string::npos);
    CHECK(p.has_uniform("u_weights"));
    CHECK(p.has_uniform("u_weights[0]"));
    CHECK(p.has_uniform("u_weights[3]"));
    CHECK_FALSE(p.has_uniform("u_weights[4]"));
}

TEST_CASE("uniforms: an unknown or optimised-out name names the program and lists the uniforms") {
    fw::Program p = uniforms_program();
    check_mentions(error_of([&] { p.set("u_colour", glm::vec3(1)); }),
                   {"no active uniform 'u_colour'", "optimised out", "tests/uniforms.vert",
                    "tests/uniforms.frag", "Active uniforms: ", "u_color: vec3"});
    check_mentions(error_of([&] { p.set("u_unused", 1.0f); }),
                   {"no active uniform 'u_unused'", "appears in shaders/tests/uniforms.frag",
                    "optimised out", "u_mvp: mat4"});
}

TEST_CASE("uniforms: set_if_active skips an optimised-out uniform but not a misspelt one") {
    fw::Program p = uniforms_program();
    // u_unused is declared in uniforms.frag but read by nothing: not active.
    CHECK_FALSE(p.set_if_active("u_unused", 1.0f));
    CHECK(p.set_if_active("u_color", glm::vec3(0.25f, 0.5f, 1.0f)));
    float color[3] = {0, 0, 0};
    glGetUniformfv(p.id(), glGetUniformLocation(p.id(), "u_color"), color);
    CHECK(color[1] == 0.5f);
    // A name in none of the program's files is an error, as with set().
    check_mentions(error_of([&] { p.set_if_active("u_colour", glm::vec3(1)); }),
                   {"no active uniform 'u_colour'", "misspelt", "Active uniforms: "});
    // An active uniform with a value of the wrong type is still refused.
    CHECK_THROWS_AS(p.set_if_active("u_color", 1.0f), fw::Error);
}

TEST_CASE("uniforms: a value of the wrong type names the declared and the given type") {
    fw::Program p = uniforms_program();
    check_mentions(error_of([&] { p.set("u_mvp", glm::vec3(1)); }),
                   {"'u_mvp' is declared mat4 but was set with vec3", "tests/uniforms.frag"});
    check_mentions(error_of([&] { p.set("u_count", 2.0f); }),
                   {"'u_count' is declared int but was set with float"});
    check_mentions(error_of([&] { p.set("u_flag", 1.0f); }),
                   {"'u_flag' is declared bool but was set with float"});
    check_mentions(error_of([&] { p.set("u_color", glm::vec4(1)); }),
                   {"declared vec3 but was set with vec4"});
    check_mentions(error_of([&] { p.set("u_weights", std::vector<glm::vec3>{glm::vec3(1)}); }),
                   {"declared float[4] but was set with vec3[1]"});
}

TEST_CASE("uniforms: an array longer than declared names both sizes") {
    fw::Program p = uniforms_program();
    check_mentions(error_of([&] { p.set("u_weights", std::vector<float>(5, 1.0f)); }),
                   {"'u_weights' is declared float[4] but was set with float[5]"});
    check_mentions(error_of([&] { p.set("u_weights[2]", std::vector<float>(3, 1.0f)); }),
                   {"float[4]", "float[3]", "from element 2", "room for 2"});
    check_mentions(error_of([&] { p.set("u_color", std::vector<glm::vec3>(2)); }),
                   {"declared vec3 but was set with vec3[2]"});
    check_mentions(error_of([&] { p.set("u_weights", std::vector<float>{}); }), {"empty array"});
}

TEST_CASE("uniforms: values arrive, whether or not the program is in use") {
    fw::Program p = uniforms_program();
    glUseProgram(0);  // glProgramUniform needs no glUseProgram
    p.set("u_color", glm::vec3(0.25f, 0.5f, 0.75f));
    p.set("u_count", 3);
    p.set("u_mask", 7u);
    p.set("u_flag", true);
    p.set("u_texture", 2);  // samplers take the unit as an int
    glm::mat4 mvp = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3));
    p.set("u_mvp", mvp);
    glm::mat3 tint(2.0f);
    p.set("u_tint", tint);

    float color[3] = {};
    glGetUniformfv(p.id(), glGetUniformLocation(p.id(), "u_color"), color);
    CHECK(color[0] == 0.25f);
    CHECK(color[1] == 0.5f);
    CHECK(color[2] == 0.75f);
    CHECK(uniform_int(p, "u_count") == 3);
    CHECK(uniform_int(p, "u_flag") == 1);
    CHECK(uniform_int(p, "u_texture") == 2);
    GLuint mask = 0;
    glGetUniformuiv(p.id(), glGetUniformLocation(p.id(), "u_mask"), &mask);
    CHECK(mask == 7u);
    float m[16] = {};
    glGetUniformfv(p.id(), glGetUniformLocation(p.id(), "u_mvp"), m);
    // Column-major: the translation is the fourth column, elements 12..14.
    CHECK(m[12] == 1.0f);
    CHECK(m[13] == 2.0f);
    CHECK(m[14] == 3.0f);
    CHECK(m[0] == 1.0f);
    CHECK(m[3] == 0.0f);

    // bool takes bool and int.
    p.set("u_flag", false);
    CHECK(uniform_int(p, "u_flag") == 0);
    p.set("u_flag", 1);
    CHECK(uniform_int(p, "u_flag") == 1);
    // set(name, double) stores a float, so set("x", 0.5) needs no suffix.
    p.set("u_weights[1]", 0.5);
    CHECK(uniform_float(p, "u_weights[1]") == 0.5f);
}

TEST_CASE("uniforms: arrays are set from element 0 or from element i") {
    fw::Program p = uniforms_program();
    p.set("u_weights", std::vector<float>{1, 2, 3, 4});
    CHECK(uniform_float(p, "u_weights[0]") == 1.0f);
    CHECK(uniform_float(p, "u_weights[3]") == 4.0f);
    p.set("u_weights[0]", std::vector<float>{5});
    CHECK(uniform_float(p, "u_weights[0]") == 5.0f);
    CHECK(uniform_float(p, "u_weights[1]") == 2.0f);
    p.set("u_weights[2]", std::vector<float>{7, 8});
    CHECK(uniform_float(p, "u_weights[1]") == 2.0f);
    CHECK(uniform_float(p, "u_weights[2]") == 7.0f);
    CHECK(uniform_float(p, "u_weights[3]") == 8.0f);

    // And by rendering: pixel column x of a 4x1 target shows u_palette[x].
    fw::Program palette = fw::Program::from_files({"tests/position.vert", "tests/palette.frag"});
    const std::vector<glm::vec3> colours = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
    palette.set("u_palette", colours);
    palette.set("u_palette[3]", glm::vec3(1, 0, 1));  // a single element by name
    const std::vector<glm::vec3> quad = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0},
                                         {-1, -1, 0}, {1, 1, 0},  {-1, 1, 0}};
    fw::Buffer vbo = fw::Buffer::from(quad, GL_ARRAY_BUFFER, "palette quad");
    fw::VertexLayout layout(sizeof(glm::vec3));
    layout.add({0, 3, GL_FLOAT, 0, false, false});
    fw::VertexArray vao({&vbo, layout, nullptr, GL_UNSIGNED_INT, "palette quad"});
    fw::Framebuffer fb({4, 1, "palette"});
    fb.bind();
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    palette.use();
    vao.draw(GL_TRIANGLES, 6);
    fw::check_gl("palette draw");
    fw::Image img = fb.read_color();
    bool pass = fw::test::probe_rgb(img, 0, 0, colours[0]);
    pass = fw::test::probe_rgb(img, 1, 0, colours[1]) && pass;
    pass = fw::test::probe_rgb(img, 2, 0, colours[2]) && pass;
    pass = fw::test::probe_rgb(img, 3, 0, glm::vec3(1, 0, 1)) && pass;
    CHECK(pass);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}
