// `course bless`: re-renders the reference image of every checkpoint with an
// image check, through the same child as `course grade`, and writes
// labs/NN_name/reference/CHECKPOINT.png. References are repository files:
// bless, look at them, commit them. The backend follows the same rule as
// `course grade` (--backend, else $LAB_BACKEND, else auto: EGL, then OSMesa);
// the two backends render every checkpoint alike (tests/tools/test_backends).
// `course warm-cache` runs the same children to fill a shader cache (Mesa's or
// NVIDIA's).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "framework/error.hpp"
#include "grading/commands/commands.hpp"
#include "grading/commands/lab_sources.hpp"
#include "grading/diagnosis/state_diff.hpp"
#include "grading/judge/checks.hpp"
#include "grading/judge/course_seed.hpp"

namespace grading {

namespace {

// "egl (surfaceless, llvmpipe (LLVM 15.0.6, 256 bits))": what the child says it
// rendered on, for the lines that name each written file. Informational only.
std::string rendered_on(const ChildOutputs& outputs) {
    std::string bytes, why;
    if (!outputs.read("child.json", 64 * 1024, bytes, why)) return "backend unknown: " + why;
    const nlohmann::json child = nlohmann::json::parse(bytes, nullptr, false);
    if (!child.is_object() || !child.contains("context") || !child["context"].is_object())
        return "backend unknown";
    const nlohmann::json& c = child["context"];
    return c.value("backend", "?") + " (" + c.value("platform", "?") + ", " +
           c.value("gl_renderer", "?") + ")";
}

}  // namespace

int bless_command(const BlessOptions& options) {
    std::vector<LabData> labs = select_labs(discover_labs(source_root()), options.labs);
    for (LabData& lab : labs) parse_checks(lab);
    const std::string lab_binary = resolve_lab_binary(options.lab_binary);
    require_lab_up_to_date(lab_binary, false, options.labs);
    ChildLimits limits;
    limits.timeout_seconds = 300.0;  // every image checkpoint of a lab in one child
    // The course's seed, once: every grading after draws the same cases.
    unsigned made = 0;
    if (make_course_seed(source_root(), made))
        std::printf(
            "wrote %s (seed %u): the unit checks' random cases come from it; commit it "
            "with the references\n",
            kCourseSeedFile, made);

    for (const LabData& lab : labs) {
        const LabPlan plan = plan_lab(lab, 0, PlanFor::Blessing);
        if (plan.renders.empty()) {
            std::printf("%s: no image checks, nothing to bless\n", lab.id.c_str());
            continue;
        }
        LabChild child = run_lab_child(lab_binary, plan.job, options.backend, limits, nullptr);
        if (!child.run.ok()) {
            std::fprintf(stderr,
                         "course: bless: the lab child for '%s' %s; nothing written for it\n%s",
                         lab.id.c_str(), child.run.status.text().c_str(),
                         indented_tail(child.run.log, 20).c_str());
            return 2;
        }
        // Every image and record first: a lab is blessed whole or not at all.
        std::vector<fw::Image> images(plan.renders.size());
        std::vector<std::string> records(plan.renders.size());
        for (size_t i = 0; i < plan.renders.size(); ++i) {
            std::string why;
            if (!read_rendered(*child.outputs, plan.renders[i], images[i], why) ||
                !child.outputs->read(plan.renders[i].checkpoint + ".record.json", 16 * kMiB,
                                     records[i], why)) {
                std::fprintf(stderr,
                             "course: bless: %s, checkpoint '%s': %s; nothing written for '%s'\n",
                             lab.id.c_str(), plan.renders[i].checkpoint.c_str(), why.c_str(),
                             lab.id.c_str());
                return 2;
            }
        }
        std::filesystem::create_directories(lab.reference_dir());
        const std::string backend = rendered_on(*child.outputs);
        for (size_t i = 0; i < plan.renders.size(); ++i) {
            const std::string rel = lab.reference(plan.renders[i].checkpoint);
            fw::write_png(lab.root + "/" + rel, images[i]);
            // What each draw was told, beside it (grading/diagnosis/state_diff.hpp).
            write_reference_record(lab, plan.renders[i].checkpoint, records[i]);
            std::printf("wrote %s (%dx%d, %s)\n", rel.c_str(), images[i].width, images[i].height,
                        backend.c_str());
        }
    }
    return 0;
}

int warm_cache_command(const WarmCacheOptions& options) {
    std::vector<LabData> labs = select_labs(discover_labs(source_root()), options.labs);
    for (LabData& lab : labs) parse_checks(lab);
    const std::string lab_binary = resolve_lab_binary(options.lab_binary);
    require_lab_up_to_date(lab_binary, false, options.labs);
    std::error_code ec;
    std::filesystem::create_directories(options.dir, ec);
    if (ec || !std::filesystem::is_directory(options.dir))
        throw fw::UsageError("cannot create the shader cache directory '" + options.dir +
                             "': " + ec.message());
    ChildLimits limits;
    limits.timeout_seconds = 300.0;
    ShaderCache cache;
    cache.dir = std::filesystem::absolute(options.dir).string();
    cache.shared = true;
    // Each lab twice. The first run compiles the GLSL and caches the
    // programs; the second loads them from the cache, as every graded
    // submission does, and llvmpipe compiles (and caches) code of its own for
    // programs that come from the cache, which the first run never asked for.
    // With the first run's cache alone, a grading of every lab still spent
    // twice as long in LLVM (0.46-0.49 against 0.23-0.24 s of CPU, Mesa 22.3).
    for (const LabData& lab : labs) {
        const LabPlan plan = plan_lab(lab, 0, PlanFor::Grading);
        double seconds[2] = {0, 0};
        for (double& s : seconds) {
            LabChild child =
                run_lab_child(lab_binary, plan.job, options.backend, limits, nullptr, cache);
            if (!child.run.ok()) {
                std::fprintf(stderr, "course: warm-cache: the lab child for '%s' %s\n%s",
                             lab.id.c_str(), child.run.status.text().c_str(),
                             indented_tail(child.run.log, 20).c_str());
                return 2;
            }
            s = child.run.seconds;
        }
        std::printf("warmed %s (%zu frames, %.2f s, then %.2f s from the cached programs)\n",
                    lab.id.c_str(), plan.renders.size(), seconds[0], seconds[1]);
    }
    const std::uint64_t bytes = directory_bytes(cache.dir);
    std::printf("shader cache in %s: %s\n", cache.dir.c_str(), mib_text(bytes).c_str());
    if (bytes == 0)
        std::fprintf(stderr,
                     "course: warm-cache: warning: the driver wrote no shader cache into %s: it "
                     "keeps none that course can direct (Mesa's and NVIDIA's can be), so "
                     "--shader-cache will not spare any compiling\n",
                     cache.dir.c_str());
    return 0;
}

}  // namespace grading
