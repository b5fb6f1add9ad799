#include "grading/commands/grade_setup.hpp"

#include <future>
#include <thread>

#include "grading/diagnosis/state_diff.hpp"
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

SandboxProbe probe_sandbox() {
    SandboxProbe probe;
    std::future<std::unique_ptr<CgroupRoot>> cgroups =
        std::async(std::launch::async, [&probe] { return CgroupRoot::open(probe.cgroups_why); });
    probe.namespaces = namespaces_usable(probe.namespaces_why);
    probe.cgroups = cgroups.get();
    return probe;
}

}  // namespace grading
