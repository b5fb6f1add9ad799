// `course autograde`'s reports of a submission it could not grade
// (gradescope.hpp): every check failed with the reason; for PrairieLearn, a
// results.json that says the submission was not gradable.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "framework/error.hpp"
#include "grading/judge/checks.hpp"
#include "grading/platforms/autograder.hpp"
#include "grading/release/release.hpp"
#include "grading/report/prairielearn_results.hpp"
#include "grading/report/report_text.hpp"
#include "grading/report/reports.hpp"
#include "grading/run/child.hpp"

namespace grading {

std::string log_tail(const std::string& path, int lines) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw fw::Error("cannot read the log '" + path + "': check that it exists and is readable");
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    const std::streamoff from = std::max<std::streamoff>(0, size - std::streamoff(kMiB));
    in.seekg(from);
    std::string text(static_cast<size_t>(size - from), '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    while (!text.empty() && text.back() == '\n') text.pop_back();
    size_t start = text.size();
    for (int n = 0; n < lines && start != std::string::npos && start > 0; ++n)
        start = text.rfind('\n', start - 1);
    return start == std::string::npos || start == text.size() ? text : text.substr(start + 1);
}

LabResult not_run_lab(const LabData& lab, const std::string& reason, const std::string& log,
                      const std::string& out_dir) {
    // The checks, named and scored as `course grade` names them, judged on the
    // outputs of a child that never ran: an empty work directory.
    WorkDir empty(nullptr);
    ChildRun none;
    none.status = LabStatus::failed(reason);
    const ChildOutputs outputs(empty.path(), none, ChildLimits{});
    LabResult result;
    result.lab = lab.id;
    result.status = LabStatus::failed(reason);
    result.log = log;
    result.checks = judge_lab(lab, plan_lab(lab, 0, PlanFor::Grading), outputs, out_dir);
    for (CheckResult& check : result.checks) check.output.clear();  // the status says why
    return result;
}

int not_graded_command(const std::string& reason, const std::string& log_file,
                       const std::string& out_dir, ResultsFormat format,
                       const std::vector<std::string>& labs, HiddenAs hidden_as, bool print) {
    const std::string log = log_file.empty() ? "" : log_tail(log_file, 200);
    GradeRun run;
    for (LabData& lab : select_labs(discover_labs(source_root()), labs)) {
        parse_checks(lab);
        run.labs.push_back(not_run_lab(lab, reason, "", out_dir));
    }
    write_reports(run, out_dir, {ResultsFormat::Gradescope, "", hidden_as});
    const std::string path = report::in_dir(out_dir, "results.json");
    if (format == ResultsFormat::PrairieLearn) {
        report::write_text_file(path, prairielearn_not_gradable_json(reason, log));
        if (print) std::printf("%s", summary_table(run).c_str());
        return 1;
    }

    // results.json's overall output: the reason once and the log, rather than
    // the reason once per lab.
    nlohmann::ordered_json results = nlohmann::ordered_json::parse(read_file(path));
    results["output"] =
        report::clean_text("0/" + report::points(run.max_score()) + " points: " + reason +
                           (log.empty() ? "" : "\n\n" + log) + "\n");
    report::write_text_file(path, results.dump(2) + "\n");
    if (print) std::printf("%s", summary_table(run).c_str());
    return 1;
}

}  // namespace grading
