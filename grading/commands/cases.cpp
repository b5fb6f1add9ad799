// `course cases LAB`: the lab's recorded unit cases (grading/judge/cases.hpp),
// as `course release` writes them into the student's copy, for staff to look
// at (their size, what the student's course will judge from).
#include "grading/judge/cases.hpp"

#include <cstdio>
#include <filesystem>

#include "grading/commands/commands.hpp"

namespace grading {

int cases_command(const CasesOptions& options) {
    std::vector<LabData> labs = select_labs(discover_labs(source_root()), {options.lab});
    LabData& lab = labs.at(0);
    parse_checks(lab);
    const nlohmann::json cases = record_unit_cases(lab, options.seed, options.max_random);
    const std::string out = options.out.empty() ? unit_cases_path(lab) : options.out;
    write_unit_cases(out, cases);
    std::printf("%s: %zu unit and buffer checks, %zu functions, %ju bytes\n", out.c_str(),
                cases["checks"].size(), cases["functions"].size(),
                static_cast<uintmax_t>(std::filesystem::file_size(out)));
    return 0;
}

}  // namespace grading
