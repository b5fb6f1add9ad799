// Lab 12's scenes (scenes.hpp says what each is).
#include "scenes.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace shadows {

namespace {

// The rectangle with corners a and c, b and d the other two, as two triangles.
void quad(Mesh& m, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    for (const glm::vec3& p : {a, b, c, a, c, d}) m.push_back({p});
}

Mesh horizontal(float y, float x0, float x1, float z0, float z1) {
    Mesh m;
    quad(m, {x0, y, z1}, {x1, y, z1}, {x1, y, z0}, {x0, y, z0});
    return m;
}

}  // namespace

Mesh ground() { return horizontal(0.0f, -2.0f, 2.0f, -2.0f, 2.0f); }
Mesh caster_a() { return horizontal(1.0f, -0.5f, 0.5f, -0.5f, 0.5f); }
Mesh caster_b() { return horizontal(2.0f, 0.0f, 1.0f, 0.0f, 1.0f); }

Mesh fog_planes() {
    Mesh m;
    for (int k = 0; k < 4; ++k) {
        const float x0 = float(k) - 2.0f, x1 = x0 + 1.0f, z = -(2.0f + 2.0f * float(k));
        quad(m, {x0, -1.5f, z}, {x1, -1.5f, z}, {x1, 1.5f, z}, {x0, 1.5f, z});
    }
    return m;
}

Mesh wall() {
    Mesh m;
    quad(m, {0.0f, 0.0f, 0.5f}, {0.0f, 0.0f, -0.5f}, {0.0f, 1.0f, -0.5f}, {0.0f, 1.0f, 0.5f});
    return m;
}

glm::mat4 top_view() { return glm::lookAt(glm::vec3(0, 5, 0), glm::vec3(0), glm::vec3(0, 0, -1)); }
glm::mat4 top_projection() { return glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, 0.1f, 10.0f); }
glm::mat4 fog_projection() { return glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, 0.1f, 20.0f); }

glm::mat4 light_view_projection() {
    return glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, 0.5f, 4.5f) *
           glm::lookAt(glm::vec3(2, 2, 0), glm::vec3(0), glm::vec3(0, 1, 0));
}

}  // namespace shadows
