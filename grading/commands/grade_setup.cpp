#include "grading/commands/grade_setup.hpp"

#include <future>
#include <nlohmann/json.hpp>
#include <thread>

#include "framework/error.hpp"
#include "grading/diagnosis/state_diff.hpp"
#include "grading/release/release.hpp"
#include "grading/run/parallel.hpp"

namespace grading {

std::vector<LabData> labs_to_grade(const std::vector<LabData>& all,
                                   const std::vector<std::string>& names) {
    std::vector<LabData> labs = select_labs(all, names);
    parallel_for(labs.size(), static_cast<int>(std::thread::hardware_concurrency()), [&](size_t i) {
        parse_checks(labs[i]);
        check_reference_records(labs[i]);
    });
    return labs;
}

// --not-built FILE: a JSON object from a lab's folder to what the compiler
// said of its C++ (`course autograde`); none without the option.
std::map<std::string, std::string> read_not_built(const std::string& file) {
    if (file.empty()) return {};
    try {
        return nlohmann::json::parse(read_file(file)).get<std::map<std::string, std::string>>();
    } catch (const std::exception& e) {
        throw fw::UsageError("--not-built " + file +
                             ": not a JSON object of lab folders and the compiler's output (" +
                             e.what() + ")");
    }
}

SandboxProbe probe_sandbox() {
    SandboxProbe probe;
    std::future<std::unique_ptr<CgroupRoot>> cgroups =
        std::async(std::launch::async, [&probe] { return CgroupRoot::open(probe.cgroups_why); });
    probe.namespaces = namespaces_usable(probe.namespaces_why);
    probe.cgroups = cgroups.get();
    return probe;
}

}  // namespace grading
