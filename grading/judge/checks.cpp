// Validating the checks of a data file, and planning the child's job.
#include "grading/judge/checks.hpp"

#include <algorithm>
#include <map>
#include <random>
#include <set>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/diagnosis/diagnosis.hpp"
#include "grading/judge/cases.hpp"
#include "grading/judge/check_where.hpp"
#include "grading/judge/judge_buffer.hpp"
#include "grading/units/reference.hpp"

namespace grading {

namespace {

using nlohmann::json;

// FNV-1a: the same on every platform, unlike std::hash.
unsigned fnv1a(const std::string& s) {
    unsigned h = 2166136261u;
    for (unsigned char c : s) h = (h ^ c) * 16777619u;
    return h;
}

// Fields each kind accepts besides "kind", "points" and "size"; anything
// else is a typo that would otherwise be ignored.
const std::map<CheckKind, std::set<std::string>> kFields = {
    {CheckKind::Image, {"tolerance", "radius", "max_fail_fraction"}},
    {CheckKind::Probe, {"at", "ndc", "color", "depth", "tolerance"}},
    {CheckKind::Stat, {"stat", "equals", "min", "max", "tolerance"}},
    {CheckKind::Unit, {"function", "random", "edge", "tolerance"}},
    {CheckKind::Forbidden, {"files", "names", "rule"}},
    {CheckKind::Buffer, {"buffer", "reference", "tolerance"}},
    {CheckKind::Portable, {}},
    {CheckKind::State, {}},
};
const char* const kKinds = "image, probe, stat, unit, forbidden, buffer, portable, state";

bool is_size(const json& v) {
    return v.is_array() && v.size() == 2 && v[0].is_number_integer() && v[1].is_number_integer();
}

// The frame size of a checkpoint: the one its checks give, else 512 x 512.
// (A malformed "size" is reported when its own check is validated.)
std::pair<int, int> render_size(const fw::Checkpoint& cp) {
    for (const json& check : cp.checks)
        if (check.is_object() && check.contains("size") && is_size(check["size"]))
            return {check["size"][0].get<int>(), check["size"][1].get<int>()};
    return {512, 512};
}

// The check's kind, once it is known and every field is one that kind takes.
CheckKind validated_kind(const CheckWhere& w, const json& check) {
    if (!check.is_object())
        w.fail("", "must be an object like {\"kind\": \"image\", \"points\": 1}");
    if (!check.contains("kind") || !check["kind"].is_string())
        w.fail("kind", std::string("is missing: it must be one of ") + kKinds);
    const std::string name = check["kind"];
    auto fields = std::find_if(kFields.begin(), kFields.end(),
                               [&](const auto& f) { return name == name_of(f.first); });
    if (fields == kFields.end()) w.fail("kind", "is \"" + name + "\"; it must be one of " + kKinds);
    const CheckKind kind = fields->first;
    std::vector<std::string> allowed = {"kind", "points"};
    if (kind != CheckKind::Unit && kind != CheckKind::Forbidden) allowed.push_back("size");
    allowed.insert(allowed.end(), fields->second.begin(), fields->second.end());
    for (const auto& [field, value] : check.items()) {
        (void)value;
        if (std::find(allowed.begin(), allowed.end(), field) == allowed.end())
            w.fail(field, "is not a field of a " + name +
                              " check; its fields are: " + fw::join(allowed, ", "));
    }
    return kind;
}

// "points", and "size", which every check of a checkpoint must share.
double parse_points_and_size(const CheckWhere& w, const json& check, const fw::Checkpoint& cp) {
    if (!check.contains("points"))
        w.fail("points", "is missing: how many points the check is worth");
    const double points = w.number("points", 0, 1000);
    if (!check.contains("size")) return points;
    const json& size = check["size"];
    if (!is_size(size) || size[0] < 1 || size[1] < 1 || size[0] > 8192 || size[1] > 8192)
        w.fail("size", "must be [width, height], integers from 1 to 8192, got " + size.dump());
    auto [width, height] = render_size(cp);
    if (size[0] != width || size[1] != height)
        w.fail("size",
               "differs from another check's size; the checks of one checkpoint share one frame");
    return points;
}

ImageCheck parse_image(const CheckWhere& w) {
    ImageCheck c;
    if (w.has("tolerance")) c.tolerance = w.integer("tolerance", 0, 255);
    if (w.has("radius")) c.radius = w.integer("radius", 0, 16);
    if (w.has("max_fail_fraction")) c.max_fail_fraction = w.number("max_fail_fraction", 0, 1);
    return c;
}

ProbeCheck parse_probe(const CheckWhere& w, const fw::Checkpoint& cp) {
    ProbeCheck c;
    if (w.has("at") == w.has("ndc")) w.fail("at", "or \"ndc\": a probe needs exactly one of them");
    if (w.has("at")) {
        auto [width, height] = render_size(cp);
        std::vector<double> at = w.numbers("at", 2, 2, 0, 8192);
        if (!w.get("at")[0].is_number_integer() || !w.get("at")[1].is_number_integer() ||
            at[0] >= width || at[1] >= height)
            w.fail("at", "must be an integer pixel inside the " + std::to_string(width) + "x" +
                             std::to_string(height) + " frame, got " + w.get("at").dump());
        c.at = std::array<int, 2>{static_cast<int>(at[0]), static_cast<int>(at[1])};
    } else {
        const std::vector<double> ndc = w.numbers("ndc", 2, 2, -1, 1);
        c.ndc = {ndc[0], ndc[1]};
    }
    if (w.has("color") == w.has("depth"))
        w.fail("color", "or \"depth\": a probe needs exactly one of them");
    if (w.has("color")) c.color = w.numbers("color", 3, 4, 0, 1);
    if (w.has("depth")) c.depth = w.number("depth", 0, 1);
    c.tolerance = w.has("tolerance") ? w.number("tolerance", 0, 1)
                  : c.reads_depth()  ? kDepthTolerance
                                     : kColorTolerance;
    return c;
}

StatCheck parse_stat(const CheckWhere& w) {
    StatCheck c;
    if (!w.has("stat") || !w.get("stat").is_string() || w.get("stat").get<std::string>().empty())
        w.fail("stat", "must name a value of the frame's stats, e.g. \"primitives_generated\"");
    if (!w.has("equals") && !w.has("min") && !w.has("max"))
        w.fail("equals", "(or \"min\"/\"max\") is missing: what the value must be");
    if (w.has("equals") && (w.has("min") || w.has("max")))
        w.fail("equals", "cannot be combined with \"min\"/\"max\"");
    c.stat = w.get("stat");
    if (w.has("equals")) c.equals = w.get("equals");
    if (w.has("min")) c.min = w.number("min", -1e300, 1e300);
    if (w.has("max")) c.max = w.number("max", -1e300, 1e300);
    if (w.has("tolerance")) {
        c.tolerance = w.number("tolerance", 0, 1e300);
        if (!w.has("equals") || !w.get("equals").is_number())
            w.fail("tolerance", "only applies to a numeric \"equals\"");
    }
    return c;
}

// A recorded reference's check takes the random cases recorded for it.
void take_recorded(const CheckWhere& w, const LabData& lab, const RecordedChecks& recorded,
                   const std::string& checkpoint, size_t index, UnitCheck& c) {
    const auto found = recorded.find({checkpoint, index});
    if (found == recorded.end() || found->second.function != c.function)
        w.fail("function", "has no cases for this check in " + unit_cases_path(lab) +
                               ", which course judges it from (it has no compiled reference); "
                               "record the file again with course release");
    c.recorded = found->second.random;
}

UnitCheck parse_unit(const CheckWhere& w, const LabData& lab, const RecordedChecks& recorded,
                     const std::string& checkpoint, size_t index) {
    UnitCheck c;
    if (!w.has("function") || !w.get("function").is_string())
        w.fail("function", "must name a unit function, e.g. \"translate\"");
    const ReferenceUnit* ref = nullptr;
    try {
        ref = &find_reference(lab.id, w.get("function").get_ref<const std::string&>());
    } catch (const fw::Error& e) {
        w.fail("function", e.what());
    }
    c.function = w.get("function");
    if (w.has("random")) c.random = w.integer("random", 0, 100000);
    if (w.has("tolerance")) c.tolerance = w.number("tolerance", 0, 1);
    if (ref->recorded) take_recorded(w, lab, recorded, checkpoint, index, c);
    if (!w.has("edge")) return c;
    if (!w.get("edge").is_array()) w.fail("edge", "must be a list of argument lists");
    for (const json& args : w.get("edge")) {
        try {
            // The reference accepts them, so the lab's signature does.
            ref->function.call(args);
        } catch (const std::exception& e) {
            w.fail("edge", "has the argument list " + args.dump() + " that '" + ref->function.name +
                               "' does not take: " + e.what());
        }
        c.edge.push_back(args);
    }
    return c;
}

// A list of non-empty strings in `field`.
std::vector<std::string> strings(const CheckWhere& w, const std::string& field,
                                 const std::string& example) {
    if (!w.has(field) || !w.get(field).is_array() || w.get(field).empty())
        w.fail(field, "must be a non-empty list of strings, e.g. " + example);
    std::vector<std::string> out;
    for (const json& s : w.get(field)) {
        if (!s.is_string() || s.get<std::string>().empty())
            w.fail(field, "must be a non-empty list of strings, e.g. " + example);
        out.push_back(s);
    }
    return out;
}

// The files are read when judged: a missing one fails the check, named.
ForbiddenCheck parse_forbidden(const CheckWhere& w) {
    ForbiddenCheck c;
    c.files = strings(w, "files", "[\"labs/01_transforms/transforms_math.cpp\"]");
    c.names = strings(w, "names", "[\"glm::translate\"]");
    if (!w.has("rule") || !w.get("rule").is_string() || w.get("rule").get<std::string>().empty())
        w.fail("rule", "must be the sheet's sentence that forbids these names");
    c.rule = w.get("rule");
    return c;
}

Check parse_check(const LabData& lab, const fw::Checkpoint& cp, size_t index, const json& check,
                  const RecordedChecks& recorded) {
    CheckWhere w(lab, cp, index, check);
    Check c;
    c.kind = validated_kind(w, check);
    c.points = parse_points_and_size(w, check, cp);
    switch (c.kind) {
        case CheckKind::Image:
            c.spec = parse_image(w);
            break;
        case CheckKind::Probe:
            c.spec = parse_probe(w, cp);
            break;
        case CheckKind::Stat:
            c.spec = parse_stat(w);
            break;
        case CheckKind::Unit:
            c.spec = parse_unit(w, lab, recorded, cp.name, index);
            break;
        case CheckKind::Forbidden:
            c.spec = parse_forbidden(w);
            break;
        case CheckKind::Buffer: {
            const auto found = recorded.find({cp.name, index});
            c.spec = parse_buffer(
                w, lab, cp,
                found != recorded.end() && found->second.buffer ? &*found->second.buffer : nullptr);
            break;
        }
        case CheckKind::Portable:
            c.spec = PortableCheck{};
            break;
        case CheckKind::State:
            // The solution's record is blessed with the checkpoint's image.
            if (!std::any_of(cp.checks.begin(), cp.checks.end(), [](const json& other) {
                    return other.is_object() && other.value("kind", "") == "image";
                }))
                w.fail("kind",
                       "is \"state\", which needs an image check in the same checkpoint: "
                       "course bless keeps the solution's record with its image");
            c.spec = StateCheck{};
            break;
    }
    return c;
}

// The unit checks of checkpoint `cp` in the plan: each check's cases, and
// a call of the job for each case, numbered from `next_id`.
void plan_units(LabPlan& plan, const std::string& lab_id, const fw::Checkpoint& cp,
                const std::vector<Check>& checks, std::mt19937& rng, int& next_id) {
    for (size_t i = 0; i < checks.size(); ++i) {
        if (checks[i].kind != CheckKind::Unit) continue;
        const UnitCheck& check = checks[i].as<UnitCheck>();
        const ReferenceUnit& ref = find_reference(lab_id, check.function);
        UnitPlan unit{cp.name, i, {}};
        const int first = next_id;
        // Edge cases first: their failures, shown first, are the easiest to read.
        for (const json& args : check.edge)
            unit.cases.push_back({"u" + std::to_string(next_id++), args, true});
        if (check.recorded) {
            for (const json& args : *check.recorded)
                unit.cases.push_back({"u" + std::to_string(next_id++), args, false});
        } else {
            for (int n = 0; n < check.random; ++n)
                unit.cases.push_back(
                    {"u" + std::to_string(next_id++), random_arguments(ref, rng), false});
        }
        // One entry of the job for the check's calls, in the order of their
        // ids (the child's protocol: docs/contract.md, `course grade`).
        if (!unit.cases.empty()) {
            json args = json::array();
            for (const UnitCase& c : unit.cases) args.push_back(c.args);
            plan.job["units"].push_back(
                {{"function", ref.function.name}, {"first", first}, {"args", std::move(args)}});
        }
        plan.units.push_back(std::move(unit));
    }
}

// The job's entry for the checkpoint's render; null when none of its checks
// renders (for blessing: when it has no image check).
json render_entry(const LabData& lab, const fw::Checkpoint& cp, const std::vector<Check>& checks,
                  PlanFor what) {
    bool render = false, depth = false, buffers = false, usage = false;
    for (const Check& check : checks) {
        render =
            render || (what == PlanFor::Grading ? check.renders() : check.kind == CheckKind::Image);
        depth = depth || (what == PlanFor::Grading && check.kind == CheckKind::Probe &&
                          check.as<ProbeCheck>().reads_depth());
        buffers = buffers || (what == PlanFor::Grading && check.kind == CheckKind::Buffer);
        usage = usage || (what == PlanFor::Grading && check.kind == CheckKind::Portable);
    }
    if (!render) return nullptr;
    auto [width, height] = render_size(cp);
    // "depth": a check reads the depth buffer, so the child writes
    // NAME.pfm; "buffers": a check reads the lab's buffers (NAME.buffers.json);
    // "usage": a check reads the render's GL usage (NAME.usage.json).
    json entry = {{"name", cp.name}, {"params", cp.params}, {"width", width}, {"height", height},
                  {"depth", depth},  {"buffers", buffers},  {"usage", usage}};
    // "record": what each draw was told, for the state diff
    // (grading/diagnosis/state_diff.hpp): the solution's when blessing, a
    // submission's where the checkpoint has the solution's.
    if (what == PlanFor::Blessing || has_reference_record(lab, cp.name)) entry["record"] = true;
    return entry;
}

}  // namespace

std::string LabData::reference(const std::string& checkpoint) const {
    return "labs/" + dir + "/reference/" + checkpoint + ".png";
}

std::string LabData::reference_dir() const { return root + "/labs/" + dir + "/reference"; }

void parse_checks(LabData& lab) {
    const RecordedChecks recorded = load_unit_cases(lab);
    lab.checks.assign(lab.file.checkpoints.size(), {});
    lab.visibility.clear();
    for (size_t k = 0; k < lab.file.checkpoints.size(); ++k) {
        const fw::Checkpoint& cp = lab.file.checkpoints[k];
        lab.visibility.push_back(visibility_named(cp.visibility));
        if (!cp.checks.is_array()) continue;  // read_checkpoint_file has checked this
        for (size_t i = 0; i < cp.checks.size(); ++i)
            lab.checks[k].push_back(parse_check(lab, cp, i, cp.checks[i], recorded));
    }
    read_diagnosis_files(lab);
}

LabPlan plan_lab(const LabData& lab, unsigned seed, PlanFor what) {
    LabPlan plan;
    plan.seed = seed;
    plan.job = {{"lab", lab.id}, {"renders", json::array()}, {"units", json::array()}};
    int next_id = 0;
    for (size_t k = 0; k < lab.file.checkpoints.size(); ++k) {
        const fw::Checkpoint& cp = lab.file.checkpoints[k];
        const std::vector<Check>& checks = lab.checks.at(k);
        const json render = render_entry(lab, cp, checks, what);
        if (!render.is_null()) {
            plan.renders.push_back(
                {cp.name, render["width"].get<int>(), render["height"].get<int>()});
            plan.job["renders"].push_back(render);
        }
        if (what != PlanFor::Grading) continue;
        // One stream per checkpoint, from the course's seed, the lab and the
        // checkpoint's name: its cases depend on nothing else (which labs
        // are graded with it, the checkpoints before it, the clock).
        std::seed_seq seq{seed, fnv1a(lab.id), fnv1a(cp.name)};
        std::mt19937 rng(seq);
        plan_units(plan, lab.id, cp, checks, rng, next_id);
    }
    return plan;
}

}  // namespace grading
