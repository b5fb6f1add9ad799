// A `portable` check (docs/contract.md, Checks): GL usage that llvmpipe lets
// pass and the GL 4.3 specification leaves undefined or forbids, as the
// grading child found it in the checkpoint's render (NAME.usage.json,
// framework/trace/usage.hpp). The file is read as hostile input: size-limited,
// every entry checked, every string cut to a length a report can show.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "grading/judge/checks.hpp"
#include "grading/results/results.hpp"

namespace grading {

// The largest NAME.usage.json course reads.
constexpr std::uint64_t kUsageFileLimit = 1 * kMiB;

struct UsageFinding {
    std::string rule, call, detail;
    long long draw = 0, times = 1;
};

// The checkpoint's NAME.usage.json; false and why (missing, too large, not a
// list of findings) when it cannot be read.
bool read_usage(const ChildOutputs& outputs, const std::string& checkpoint,
                std::vector<UsageFinding>& findings, std::string& why);

// Passes when the render ended (`rendered`; else `render_why` says why not)
// with no finding. `findings` is null when the file could not be read (`why`).
void judge_portable(const std::vector<UsageFinding>* findings, const std::string& why,
                    bool rendered, const std::string& render_why, CheckResult& r);

}  // namespace grading
