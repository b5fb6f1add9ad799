// junit.xml, for CI dashboards: one <testcase> per checkpoint.
#include <sstream>
#include <vector>

#include "grading/report/by_checkpoint.hpp"
#include "grading/report/report_text.hpp"

namespace grading {
namespace report {

// One <testcase> per checkpoint (classname the lab, name the checkpoint),
// its checks' text inside, failures first.
std::string junit_xml(const GradeRun& run) {
    size_t cases = 0, failures = 0;
    std::vector<std::vector<CheckpointResult>> labs;
    for (const LabResult& lab : run.labs) {
        labs.push_back(by_checkpoint(lab));
        cases += labs.back().size();
        for (const CheckpointResult& cp : labs.back()) failures += cp.passed ? 0 : 1;
    }
    std::ostringstream x;
    x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<testsuites name=\"course grade\" tests=\"" << cases << "\" failures=\"" << failures
      << "\" time=\"" << fixed(run.seconds, 3) << "\">\n";
    for (size_t li = 0; li < run.labs.size(); ++li) {
        const LabResult& lab = run.labs[li];
        const std::string suite = escape_markup(lab.lab);
        size_t lab_failures = 0;
        for (const CheckpointResult& cp : labs[li]) lab_failures += cp.passed ? 0 : 1;
        x << "  <testsuite name=\"" << suite << "\" tests=\"" << labs[li].size() << "\" failures=\""
          << lab_failures << "\" errors=\"0\" skipped=\"0\" time=\"" << fixed(lab.seconds, 3)
          << "\">\n";
        for (const CheckpointResult& cp : labs[li]) {
            x << "    <testcase classname=\"" << suite << "\" name=\""
              << escape_markup(cp.checkpoint) << "\">\n";
            const std::string text = checkpoint_text(lab, cp);
            if (cp.passed) {
                x << "      <system-out>" << escape_markup(text) << "</system-out>\n";
            } else {
                const std::string message = checkpoint_failure(lab, cp);
                std::string kinds;
                for (const CheckResult* c : cp.checks)
                    if (!c->passed && kinds.find(name_of(c->kind)) == std::string::npos)
                        kinds += (kinds.empty() ? "" : " ") + std::string(name_of(c->kind));
                x << "      <failure message=\""
                  << escape_markup(message.empty() ? "checkpoint failed" : message) << "\" type=\""
                  << escape_markup(kinds) << "\">" << escape_markup(text) << "</failure>\n";
            }
            x << "    </testcase>\n";
        }
        if (!lab.status.ok())
            x << "    <system-err>" << escape_markup(lab.status.text() + "\n" + lab.log)
              << "</system-err>\n";
        x << "  </testsuite>\n";
    }
    x << "</testsuites>\n";
    return x.str();
}

}  // namespace report
}  // namespace grading
