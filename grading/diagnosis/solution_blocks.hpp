// Release markers, in C++ and GLSL alike: a line whose text is exactly
// `// BEGIN SOLUTION` opens a solution block and `// END SOLUTION` closes it.
// The student version drops the block; each line inside it of the form
// `<indent>// STUDENT: <code>` becomes `<indent><code>`, so both versions
// compile. Blocks do not nest. `course release` writes the student version
// of every file (grading/release/); judging reads a part's starting code
// from it (starting_code.hpp). Pure functions of a file's text.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace grading {

// Whether a file's name marks it as C++ or GLSL, the files that may hold
// release markers: .cpp .hpp .h .vert .frag .geom .tesc .tese .comp .glsl.
bool is_marked_source(const std::string& path);

// One solution block: the 1-based lines of its BEGIN and END markers.
struct SolutionBlock {
    int begin_line = 0;
    int end_line = 0;
};

// The blocks of `text`, checked: every BEGIN has its END, no block nests in
// another, a STUDENT line sits inside a block and a marker is spelt exactly.
// Throws fw::Error "PATH:LINE: what is wrong; how to fix it" (`path` only
// names the text in messages).
std::vector<SolutionBlock> solution_blocks(const std::string& text, const std::string& path);

// The student version of `text`: every block replaced by its STUDENT lines.
// Line endings (LF or CRLF) are kept; text without markers comes back as is.
std::string student_text(const std::string& text, const std::string& path);

// `text` with only block `index` (in solution_blocks order) in its student
// version and every other block, markers included, as written.
std::string student_text_of_block(const std::string& text, const std::string& path,
                                  std::size_t index);

}  // namespace grading
