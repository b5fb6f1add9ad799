// Lab 3's student parts: the camera and the projections (see camera_math.hpp
// for what each returns). GLM stores a matrix column by column: m[c][r] is
// row r, column c, so the row-r, column-c entry of the lecture's matrix
// goes into m[c][r].
#include "camera_math.hpp"

#include <cmath>

namespace projection {

glm::mat4 lookAt(glm::vec3 eye, glm::vec3 target, glm::vec3 up) {
    // BEGIN SOLUTION
    // STUDENT: (void)eye, (void)target, (void)up;
    // STUDENT: return glm::mat4(1.0f);  // TODO: rows u, v, w and the translation -(u.e, v.e, w.e)
    const glm::vec3 w = glm::normalize(eye - target);
    const glm::vec3 u = glm::normalize(glm::cross(up, w));
    const glm::vec3 v = glm::cross(w, u);
    // V = R * T(-eye): the rows of R are u, v, w (it turns u into +x, v into
    // +y, w into +z), and R * (-eye) is the last column.
    glm::mat4 V(1.0f);
    for (int c = 0; c < 3; ++c) {
        V[c][0] = u[c];
        V[c][1] = v[c];
        V[c][2] = w[c];
    }
    V[3][0] = -glm::dot(u, eye);
    V[3][1] = -glm::dot(v, eye);
    V[3][2] = -glm::dot(w, eye);
    return V;
    // END SOLUTION
}

glm::mat4 perspective(float fovy_deg, float aspect, float n, float f) {
    // BEGIN SOLUTION
    // STUDENT: (void)fovy_deg, (void)aspect, (void)n, (void)f;
    // STUDENT: return glm::mat4(1.0f);  // TODO: the lecture's perspective matrix
    // cot(fovy / 2): the point at the top of the view at distance 1 goes to y = 1.
    const float c = 1.0f / std::tan(0.5f * glm::radians(fovy_deg));
    glm::mat4 P(0.0f);
    P[0][0] = c / aspect;
    P[1][1] = c;
    // Rows 3 and 4: z_clip = A z + B and w_clip = -z, so that after the
    // divide z_ndc = -A - B / z, which is -1 at z = -n and +1 at z = -f.
    P[2][2] = (f + n) / (n - f);
    P[3][2] = 2.0f * f * n / (n - f);
    P[2][3] = -1.0f;
    return P;
    // END SOLUTION
}

glm::mat4 orthographic(float l, float r, float b, float t, float n, float f) {
    // BEGIN SOLUTION
    // STUDENT: (void)l, (void)r, (void)b, (void)t, (void)n, (void)f;
    // STUDENT: return glm::mat4(1.0f);  // TODO: scale the box to [-1, 1]^3 after moving its centre
    // to 0
    glm::mat4 O(1.0f);
    O[0][0] = 2.0f / (r - l);
    O[1][1] = 2.0f / (t - b);
    // The camera looks down -z: z = -n goes to -1, z = -f to +1.
    O[2][2] = -2.0f / (f - n);
    O[3][0] = -(r + l) / (r - l);
    O[3][1] = -(t + b) / (t - b);
    O[3][2] = -(f + n) / (f - n);
    return O;
    // END SOLUTION
}

glm::mat4 perspective01(float fovy_deg, float aspect, float n, float f) {
    // BEGIN SOLUTION
    // STUDENT: (void)fovy_deg, (void)aspect, (void)n, (void)f;
    // STUDENT: return glm::mat4(1.0f);  // TODO: as perspective(), depth to [0, 1]
    const float c = 1.0f / std::tan(0.5f * glm::radians(fovy_deg));
    glm::mat4 P(0.0f);
    P[0][0] = c / aspect;
    P[1][1] = c;
    // z_ndc = -A - B / z is 0 at z = -n and 1 at z = -f. (The same as
    // perspective() followed by z' = (z + w) / 2.)
    P[2][2] = f / (n - f);
    P[3][2] = f * n / (n - f);
    P[2][3] = -1.0f;
    return P;
    // END SOLUTION
}

glm::vec3 viewport(glm::vec3 ndc, int width, int height) {
    // BEGIN SOLUTION
    // STUDENT: (void)width, (void)height;
    // STUDENT: return ndc;  // TODO: [-1, 1] to [0, width], [0, height] and [0, 1]
    return {(ndc.x + 1.0f) * 0.5f * static_cast<float>(width),
            (ndc.y + 1.0f) * 0.5f * static_cast<float>(height), (ndc.z + 1.0f) * 0.5f};
    // END SOLUTION
}

}  // namespace projection
