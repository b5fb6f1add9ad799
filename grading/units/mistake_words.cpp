// The sentences of the usual unit-check mistakes (mistakes.hpp): what the
// report prints for a mistake recognised in mistakes.cpp.
#include <string>

#include "grading/units/mistakes.hpp"

namespace grading {

namespace {

// "your matrix", "your J (matrix [1] of the list)": what a sentence is about.
std::string subject(const ReferenceUnit& ref, const Explanation& e) {
    const ValueShape& s = ref.shape;
    const std::string noun = s.kind == ValueShape::Kind::Matrix   ? "matrix"
                             : s.kind == ValueShape::Kind::Vector ? "vector"
                                                                  : "result";
    if (!s.list || e.element < 0) return "your " + noun;
    const size_t k = static_cast<size_t>(e.element);
    const std::string index = "[" + std::to_string(k) + "]";
    return k < ref.element_names.size()
               ? "your " + ref.element_names[k] + " (" + noun + " " + index + " of the list)"
               : "your " + noun + " " + index + " of the list";
}

// "the angle", "every angle", "the angle in argument 2".
std::string angle_words(const ReferenceUnit& ref, const Explanation& e) {
    int angle_count = 0;
    for (const ArgDomain& d : ref.domains) angle_count += d.degrees ? 1 : 0;
    if (angle_count <= 1) return "the angle";
    return e.argument < 0 ? "every angle"
                          : "the angle in argument " + std::to_string(e.argument + 1);
}

// What follows the subject for the mistakes told without figures; null for
// the others.
const char* plain_cause(Mistake m) {
    switch (m) {
        case Mistake::Transpose:
            return " is the transpose of the expected one (rows and columns swapped): GLM's "
                   "m[c][r] is column c, row r, and glm::mat4(...) takes its numbers column "
                   "by column, so a matrix typed in rows into a mat4 constructor comes out "
                   "transposed; look at how you fill the matrix";
        case Mistake::Inverse:
            return " is the inverse of the expected one: it undoes the transformation "
                   "instead of applying it (a translation by -t, a scale by 1/s, a rotation "
                   "the other way, or for a view matrix the camera's placement in the world "
                   "instead of the world seen from the camera); check the signs and which "
                   "way your matrix maps points";
        case Mistake::LastColumnForDiagonal:
            return " has the diagonal's entries in the last column: a scale's factors sit on "
                   "the diagonal (m[0][0], m[1][1], m[2][2] in GLM), while the last column is "
                   "where a translation goes; put each factor on the diagonal and leave the "
                   "last column (0, 0, 0, 1)";
        case Mistake::LengthSquared:
            return " is the expected one with a direction divided by its length squared "
                   "(dot(v, v)) instead of its length: normalising divides by "
                   "sqrt(dot(v, v)), or use glm::normalize; check the division";
        case Mistake::ReversedProduct:
            return " is the product of the right matrices in reverse order: with column "
                   "vectors (p' = M p) the matrix next to the point acts first, so A * B "
                   "applies B first and differs from B * A; check the order of your "
                   "multiplications";
        case Mistake::PerspectiveDepth:
            return " has the depth interpolated perspective-correctly, weighted by 1/w like "
                   "the colours: window depth z_w is affine in the window, so it takes the "
                   "screen weights as they are (sum lambda_i z_i); keep the division by w for "
                   "the colours only";
        default:
            return nullptr;
    }
}

// What follows "is the expected one for <the angle>" for the angle mistakes;
// null for the others.
const char* angle_cause(Mistake m) {
    switch (m) {
        case Mistake::RadiansForDegrees:
            return " times pi/180: an angle already in radians was used where degrees "
                   "were meant (converted twice, or glm::radians(angle) passed to a "
                   "function that takes degrees); convert degrees to radians once, right "
                   "before sin, cos or tan";
        case Mistake::DegreesForRadians:
            return " read as radians: an angle in degrees reached sin, cos, tan or a GLM "
                   "function that takes radians without conversion; convert it with "
                   "glm::radians(angle) first";
        case Mistake::FlippedAngle:
            return " negated: a sign is flipped, typically the minus on the wrong sin term "
                   "(a positive angle turns counter-clockwise seen from the axis' positive "
                   "end); check the signs of the sin entries";
        default:
            return nullptr;
    }
}

// The translation mistake, with the entries of an n x n matrix named.
std::string translation_cause(int n) {
    std::string column, bottom;
    for (int r = 0; r + 1 < n; ++r) {
        column += (r ? ", m[" : "m[") + std::to_string(n - 1) + "][" + std::to_string(r) + "]";
        bottom += "0, ";
    }
    return " has the translation in the bottom row instead of the last column: with column "
           "vectors (p' = M p, as in GLM and GLSL) the translation is the last column, GLM's " +
           column + ", and the bottom row stays (" + bottom +
           "1); put the translation into the last column";
}

// "row 1", "rows 1 and 3" (counted from 1, as the report's rows are).
std::string rows_words(int rows) {
    std::vector<std::string> names;
    for (int r = 0; r < 31; ++r)
        if (rows & (1 << r)) names.push_back(std::to_string(r + 1));
    std::string text = names.size() == 1 ? "row " : "rows ";
    for (size_t i = 0; i < names.size(); ++i)
        text += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return text;
}

std::string flipped_axis_cause(int rows) {
    return " is the expected one with " + rows_words(rows) +
           " negated: a basis vector the matrix is built from points the wrong way (a camera "
           "looks down its -z axis, so w = normalize(eye - target), not target - eye, and "
           "u = up x w follows w); check the direction of the vector in " +
           (rows & (rows - 1) ? "those rows" : "that row") + " and of those built from it";
}

std::string normalisation_cause(bool matrix) {
    return matrix ? " is the expected one computed with a direction left unnormalised (a "
                    "rotation axis or a camera basis vector not of length 1); normalise each "
                    "direction with glm::normalize before building the matrix from it"
                  : " points the right way but is not of length 1: a direction that must be a "
                    "unit vector was not normalised; apply glm::normalize to it";
}

}  // namespace

std::string likely_mistake(const ReferenceUnit& ref, const Explanation& e) {
    std::string sentence = subject(ref, e);
    if (const char* plain = plain_cause(e.mistake))
        sentence += plain;
    else if (e.mistake == Mistake::OffByOne)
        sentence += " is the expected number plus or minus 1: " + ref.off_by_one;
    else if (const char* angle = angle_cause(e.mistake))
        sentence += " is the expected one for " + angle_words(ref, e) + angle;
    else if (e.mistake == Mistake::TranslationInBottomRow)
        sentence += translation_cause(ref.shape.columns);
    else if (e.mistake == Mistake::FlippedAxis)
        sentence += flipped_axis_cause(e.rows);
    else
        sentence += normalisation_cause(ref.shape.kind == ValueShape::Kind::Matrix);
    return "Likely mistake (" + std::string(mistake_id(e.mistake)) + "): " + sentence + ".";
}

}  // namespace grading
