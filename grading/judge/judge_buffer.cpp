// Buffer checks (judge_buffer.hpp): parsed with the expectation computed once,
// the child's buffers file read with limits, and the words of the verdict.
#include "grading/judge/judge_buffer.hpp"

#include <cmath>
#include <exception>

#include "framework/error.hpp"
#include "framework/json_glm.hpp"
#include "framework/lab_buffers.hpp"
#include "framework/text.hpp"
#include "grading/judge/cases.hpp"
#include "grading/judge/check_where.hpp"
#include "grading/judge/judge_unit.hpp"

namespace grading {

namespace {

using nlohmann::json;

// A name from the child's file as the report quotes it.
std::string shown(const std::string& name) {
    return "'" + (name.size() > 80 ? name.substr(0, 80) + "..." : name) + "'";
}

// `fn` (the reference or one of its mistakes, `what`) on the checkpoint's params.
BufferExpectation expectation(const CheckWhere& w, BufferReferenceFn fn, const json& params,
                              const std::string& what) {
    BufferExpectation e;
    try {
        e = fn(params);
    } catch (const std::exception& error) {
        w.fail("reference", "cannot be computed: " + what + " fails on the checkpoint's params " +
                                params.dump() + ": " + error.what());
    }
    if (e.components < 1 || e.components > fw::kMaxBufferComponents ||
        e.values.size() % static_cast<size_t>(e.components) != 0)
        w.fail("reference", "cannot be computed: " + what + " gives " +
                                std::to_string(e.values.size()) + " floats in elements of " +
                                std::to_string(e.components) +
                                " (components must be 1 to 64, and divide the floats)");
    return e;
}

std::string floats(size_t n) { return std::to_string(n) + (n == 1 ? " float" : " floats"); }

// "1 particle", "256 particles".
std::string counted(size_t n, const std::string& noun) {
    return std::to_string(n) + " " + (n == 1 ? noun : plural_noun(noun));
}

// What a buffer holds: "200 floats, 66 vec3 and 2 left over".
std::string holds(const fw::LabBuffer& b) {
    const size_t n = b.values.size(), c = static_cast<size_t>(b.components);
    if (c == 1) return floats(n);
    const std::string group = c <= 4 ? "vec" + std::to_string(c) : "groups of " + std::to_string(c);
    return floats(n) + ", " + std::to_string(n / c) + " " + group +
           (n % c ? " and " + std::to_string(n % c) + " left over" : "");
}

// "256 particles of 3 floats".
std::string should_hold(const BufferCheck& check) {
    const size_t c = static_cast<size_t>(check.expected.components);
    return counted(check.expected.values.size() / c, check.element) + " of " + floats(c);
}

// Elements of `seen` that are not finite or not within `tol` of `want`
// (the same layout), and the first of them.
size_t differing(const std::vector<float>& seen, const std::vector<float>& want, int components,
                 double tol, size_t& first) {
    size_t n = 0;
    const size_t c = static_cast<size_t>(components);
    for (size_t k = 0; k * c < want.size(); ++k) {
        bool same = true;
        for (size_t i = k * c; i < (k + 1) * c; ++i)
            same = same && std::isfinite(seen[i]) && std::fabs(double(seen[i]) - want[i]) <= tol;
        if (!same && n++ == 0) first = k;
    }
    return n;
}

// The mistake whose values the buffer holds, if any.
const KnownBufferMistake* matching_mistake(const BufferCheck& check, const fw::LabBuffer& seen) {
    for (const KnownBufferMistake& m : check.mistakes) {
        size_t first = 0;
        if (m.values.components == seen.components &&
            m.values.values.size() == seen.values.size() &&
            differing(seen.values, m.values.values, seen.components, check.tolerance, first) == 0)
            return &m;
    }
    return nullptr;
}

// Element k as the report prints it: "0.5", "(0.4, 1.2, 0)".
std::string element_text(const std::vector<float>& values, int components, size_t k, int decimals) {
    std::vector<double> v(values.begin() + k * components, values.begin() + (k + 1) * components);
    const auto number = [&](double x) { return unit_number(x, decimals); };
    return components == 1 ? number(v[0]) : "(" + fw::join(v, ", ", number) + ")";
}

// The check as written, with the values recorded for it.
BufferCheck with_recorded(const BufferCheck& written, const BufferCheck& recorded) {
    BufferCheck c = recorded;
    c.buffer = written.buffer;
    c.tolerance = written.tolerance;
    return c;
}

void verdict(CheckResult& r, bool pass, const std::string& output) {
    r.passed = pass;
    r.score = pass ? r.max_score : 0.0;
    r.output = output;
}

}  // namespace

BufferCheck parse_buffer(const CheckWhere& w, const LabData& lab, const fw::Checkpoint& cp,
                         const BufferCheck* recorded) {
    BufferCheck c;
    for (const char* field : {"buffer", "reference"})
        if (!w.has(field) || !w.get(field).is_string() || w.get(field).get<std::string>().empty())
            w.fail(field, std::string("must be a name, e.g. ") +
                              (field == std::string("buffer")
                                   ? "\"particles\" (a fw::LabBuffer the lab's buffers() returns)"
                                   : "\"fall\" (a COURSE_BUFFER_REFERENCE of the lab)"));
    c.buffer = w.get("buffer");
    c.reference = w.get("reference");
    if (w.has("tolerance")) c.tolerance = w.number("tolerance", 0, 1e30);
    const BufferReference* ref = nullptr;
    try {
        ref = &find_buffer_reference(lab.id, c.reference);
    } catch (const fw::Error& e) {
        if (!recorded || recorded->reference != c.reference)
            w.fail("reference", std::string(e.what()) + ", nor does " + unit_cases_path(lab) +
                                    " hold its values for this check");
        return with_recorded(c, *recorded);
    }
    std::vector<std::string> missing;
    for (const std::string& p : ref->params)
        if (!cp.params.is_object() || !cp.params.contains(p)) missing.push_back(p);
    if (!missing.empty())
        w.fail("reference", "'" + c.reference + "' computes its values from the params " +
                                fw::join(ref->params, ", ") +
                                " as the checkpoint writes them, but its \"params\" lack " +
                                fw::join(missing, ", ") + "; write them there");
    c.element = ref->element;
    c.verb = ref->verb;
    c.expected = expectation(w, ref->function, cp.params, "reference '" + c.reference + "'");
    for (const BufferMistake* m : buffer_mistakes(lab.id, c.reference))
        c.mistakes.push_back({m->id, m->sentence,
                              expectation(w, m->function, cp.params, "mistake '" + m->id + "'")});
    return c;
}

bool read_buffers(const ChildOutputs& outputs, const std::string& checkpoint,
                  std::vector<fw::LabBuffer>& buffers, std::string& why) {
    const std::string name = checkpoint + ".buffers.json";
    std::string bytes;
    try {
        if (!outputs.read(name, kBuffersFileLimit, bytes, why)) throw fw::Error(why);
        // From the bytes read (and size-checked), never from the file again.
        buffers = fw::parse_buffers(bytes, name);
    } catch (const fw::Error& e) {
        why = "no buffers: " + std::string(e.what());
        return false;
    }
    return true;
}

void judge_buffer(const BufferCheck& check, const std::vector<fw::LabBuffer>* buffers,
                  const std::string& why, CheckResult& r, const std::string& starting) {
    r.title = "buffer " + check.buffer;
    const BufferExpectation& want = check.expected;
    const std::string expected = "Expected: buffer '" + check.buffer + "' holds " +
                                 should_hold(check) + ", each float within " +
                                 fw::number_text(check.tolerance) + " of course's reference '" +
                                 check.reference + "'\nObserved: ";
    if (!buffers) return verdict(r, false, expected + why);
    const fw::LabBuffer* seen = nullptr;
    std::vector<std::string> names;
    for (const fw::LabBuffer& b : *buffers) {
        if (b.name == check.buffer) seen = &b;
        if (names.size() < 10) names.push_back(shown(b.name));
    }
    if (!seen)
        return verdict(r, false,
                       expected + "the lab wrote no buffer '" + check.buffer + "' (" +
                           (names.empty() ? "it wrote none" : "it wrote " + fw::join(names, ", ")) +
                           ")");
    std::vector<std::string> diagnosis;
    std::string named;
    if (!starting.empty()) {
        diagnosis.push_back(starting);
    } else if (const KnownBufferMistake* m = matching_mistake(check, *seen)) {
        named = ": " + m->sentence + "?";
        diagnosis.push_back("Likely mistake (" + m->id + "): " + m->sentence + ".");
    }
    for (const float v : seen->values)
        if (!std::isfinite(v)) {
            diagnosis.push_back("Your shaders wrote " + std::string(fw::non_finite_name(v)) + ": " +
                                non_finite_hint(v));
            break;
        }
    const std::string diagnosed = diagnosis.empty() ? "" : "\n" + fw::join(diagnosis, "\n");
    r.diagnosis = fw::join(diagnosis, "\n");
    if (seen->components != want.components || seen->values.size() != want.values.size())
        return verdict(r, false,
                       expected + "the buffer '" + check.buffer + "' holds " + holds(*seen) +
                           ", but should hold " + should_hold(check) + named + diagnosed);
    size_t first = 0;
    const size_t elements = want.values.size() / static_cast<size_t>(want.components);
    const size_t wrong =
        differing(seen->values, want.values, want.components, check.tolerance, first);
    if (wrong == 0)
        return verdict(r, true,
                       expected + "all " + counted(elements, check.element) + " within " +
                           fw::number_text(check.tolerance));
    const int decimals = unit_decimals(check.tolerance);
    verdict(r, false,
            expected + check.element + " " + std::to_string(first) + " " + check.verb + " " +
                element_text(seen->values, want.components, first, decimals) + " but " +
                expected_verb(check.verb) + " " +
                element_text(want.values, want.components, first, decimals) + "; " +
                std::to_string(wrong) + " of " + counted(elements, check.element) +
                (wrong == 1 ? " differs" : " differ") + named + diagnosed);
}

}  // namespace grading
