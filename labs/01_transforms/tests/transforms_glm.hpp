// Lab 1 `transforms` tests: GLM's answers for the student's matrices, shared
// by test_transforms_math.cpp (the functions) and test_transforms.cpp (the
// checkpoints' unit checks).
#pragma once

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <sstream>
#include <string>

#include "framework/json_glm.hpp"
#include "tests/support/test_support.hpp"

namespace transforms_test {

const glm::mat4 kIdentity(1.0f);

inline std::string rows_text(const glm::mat4& m) {
    std::ostringstream out;
    for (int r = 0; r < 4; ++r)
        out << "\n  [" << m[0][r] << ", " << m[1][r] << ", " << m[2][r] << ", " << m[3][r] << "]";
    return out.str();
}

// Every entry within tol * max(1, |expected|), as `course` compares units.
inline bool same_matrix(const glm::mat4& expected, const glm::mat4& observed,
                        const std::string& what, float tol = 1e-5f) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!(std::fabs(observed[c][r] - expected[c][r]) <=
                  tol * std::fmax(1.0f, std::fabs(expected[c][r])))) {
                MESSAGE(what << ": row " << r << " column " << c << " differs\nExpected:"
                             << rows_text(expected) << "\nObserved:" << rows_text(observed));
                return false;
            }
    return true;
}

inline glm::mat4 glm_rotate(float degrees, glm::vec3 axis) {
    return glm::rotate(kIdentity, glm::radians(degrees), axis);
}

// The sheet's M from GLM: T, R, S multiplied left to right in `order`.
inline glm::mat4 glm_model(float tx, float ty, float angle, float sx, float sy,
                           const std::string& order) {
    glm::mat4 m = kIdentity;
    for (char c : order)
        m = m * (c == 't'   ? glm::translate(kIdentity, {tx, ty, 0})
                 : c == 'r' ? glm_rotate(angle, {0, 0, 1})
                            : glm::scale(kIdentity, {sx, sy, 1}));
    return m;
}

// GLM's answer for a unit check's arguments (JSON, as the grader sends them).
inline glm::mat4 glm_unit(const std::string& name, const nlohmann::json& args) {
    auto number = [&](size_t i) { return args.at(i).get<float>(); };
    auto vec3 = [&](size_t i) { return fw::from_json_value<glm::vec3>(args.at(i)); };
    if (name == "translate") return glm::translate(kIdentity, vec3(0));
    if (name == "scale") return glm::scale(kIdentity, vec3(0));
    if (name == "rotateX") return glm_rotate(number(0), {1, 0, 0});
    if (name == "rotateY") return glm_rotate(number(0), {0, 1, 0});
    if (name == "rotateZ") return glm_rotate(number(0), {0, 0, 1});
    if (name == "rotate")
        return vec3(1) == glm::vec3(0) ? kIdentity : glm_rotate(number(0), vec3(1));
    REQUIRE(name == "compose");
    return glm_model(number(0), number(1), number(2), number(3), number(4),
                     args.at(5).get<std::string>().c_str());
}

}  // namespace transforms_test
