// Lab 8 `texture-mapping`: the course's references for the student's
// mappings and level of detail, written from the sheet's formulas and the GL
// specification (section 8.14.1), never from the lab's code.
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "grading/units/reference.hpp"

namespace {

// The angle about the y axis, 0 at +z, as a fraction of a turn in [0, 1].
float longitude(glm::vec3 p) {
    return static_cast<float>(std::atan2(double(p.x), double(p.z)) / (2.0 * glm::pi<double>()) +
                              0.5);
}

glm::vec2 ref_planar(glm::vec3 p) { return {0.5f * p.x + 0.5f, 0.5f * p.y + 0.5f}; }

glm::vec2 ref_cylindrical(glm::vec3 p) { return {longitude(p), 0.5f * p.y + 0.5f}; }

glm::vec2 ref_spherical(glm::vec3 p) {
    const double r = std::sqrt(double(p.x) * p.x + double(p.y) * p.y + double(p.z) * p.z);
    if (r == 0.0) return glm::vec2(0.5f);
    const double latitude = std::asin(std::fmin(1.0, std::fmax(-1.0, p.y / r)));
    return {longitude(p), static_cast<float>(latitude / glm::pi<double>() + 0.5)};
}

// rho: the longer of the pixel's two sides in texels; lambda = log2(rho).
float ref_level_of_detail(glm::vec2 d_dx, glm::vec2 d_dy, int width, int height) {
    const double w = width, h = height;
    const double x = std::hypot(d_dx.x * w, d_dx.y * h), y = std::hypot(d_dy.x * w, d_dy.y * h);
    return static_cast<float>(std::log2(std::fmax(x, y)));
}

}  // namespace

COURSE_REFERENCE(planar, &ref_planar, {grading::vec(3, -2, 2)})
COURSE_REFERENCE(cylindrical, &ref_cylindrical, {grading::vec(3, -2, 2)})
COURSE_REFERENCE(spherical, &ref_spherical, {grading::vec(3, -2, 2)})
COURSE_REFERENCE(
    level_of_detail, &ref_level_of_detail,
    {grading::vec(2, -0.1, 0.1), grading::vec(2, -0.1, 0.1), grading::integer(1, 1024),
     grading::integer(1, 1024)},
    grading::off_by_one("a mipmap level counted from 1, where level 0 is the full-size texture "
                        "and lambda = log2(rho) is 0 where a pixel spans one texel; check that "
                        "your level of detail is log2(rho) with nothing added"))
