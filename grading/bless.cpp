// `course bless`: re-renders the reference image of every checkpoint with an
// image check, through the same child as `course grade`, and writes
// labs/NN_name/reference/CHECKPOINT.png. References are repository files:
// bless, look at them, commit them.
#include <cstdio>
#include <filesystem>

#include "framework/error.hpp"
#include "grading/checks.hpp"
#include "grading/commands.hpp"

namespace grading {

int bless_command(const BlessOptions& options) {
    const std::vector<LabData> labs = select_labs(discover_labs(source_root()), options.labs);
    for (const LabData& lab : labs) validate_checks(lab);
    const std::string lab_binary = resolve_lab_binary(options.lab_binary);
    ChildLimits limits;
    limits.timeout_seconds = 300.0;  // every image checkpoint of a lab in one child

    for (const LabData& lab : labs) {
        const LabPlan plan = plan_lab(lab, 0, PlanFor::Blessing);
        if (plan.renders.empty()) {
            std::printf("%s: no image checks, nothing to bless\n", lab.id.c_str());
            continue;
        }
        LabChild child = run_lab_child(lab_binary, plan.job, options.backend, limits, nullptr);
        if (!child.run.ok()) {
            std::fprintf(
                stderr, "course: bless: the lab child for '%s' %s; nothing written for it\n%s",
                lab.id.c_str(), child.run.status.c_str(), indented_tail(child.run.log, 20).c_str());
            return 2;
        }
        // Every image first: a lab is blessed whole or not at all.
        std::vector<fw::Image> images(plan.renders.size());
        for (size_t i = 0; i < plan.renders.size(); ++i) {
            std::string why;
            if (!read_rendered(*child.outputs, plan.renders[i], images[i], why)) {
                std::fprintf(stderr,
                             "course: bless: %s, checkpoint '%s': %s; nothing written for '%s'\n",
                             lab.id.c_str(), plan.renders[i].checkpoint.c_str(), why.c_str(),
                             lab.id.c_str());
                return 2;
            }
        }
        std::filesystem::create_directories(lab.reference_dir());
        for (size_t i = 0; i < plan.renders.size(); ++i) {
            const std::string rel = lab.reference(plan.renders[i].checkpoint);
            fw::write_png(lab.root + "/" + rel, images[i]);
            std::printf("wrote %s (%dx%d, %s)\n", rel.c_str(), images[i].width, images[i].height,
                        options.backend.c_str());
        }
    }
    return 0;
}

}  // namespace grading
