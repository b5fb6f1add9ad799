#include "grading/diagnosis/state_diff.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "framework/error.hpp"
#include "framework/trace/record.hpp"
#include "grading/diagnosis/record_match.hpp"
#include "grading/diagnosis/state_words.hpp"

namespace grading {

namespace {

using nlohmann::json;

// The fields of an event, in the order they are compared: what decides
// which primitives are made comes before what is done with their fragments.
const char* const kOrder[] = {"call",
                              "args",
                              "enabled",
                              "program",
                              "vertex_array",
                              "uniforms",
                              "textures",
                              "images",
                              "uniform_buffers",
                              "storage_buffers",
                              "transform_feedback",
                              "patch_vertices",
                              "cull",
                              "polygon_mode",
                              "line_width",
                              "point_size",
                              "viewport",
                              "scissor",
                              "stencil",
                              "stencil_back",
                              "depth",
                              "blend",
                              "color_mask",
                              "framebuffer",
                              "clear_color",
                              "clear_depth",
                              "depth_mask",
                              "clear_stencil",
                              "stencil_write_mask",
                              "read_buffer",
                              "pack_alignment",
                              "pack_buffer",
                              "buffer",
                              "barriers"};

// Within a field, the parts in the order of the call that sets them, the
// colour's before alpha's (glBlendFunc sets both); others follow by name.
const char* const kPartOrder[] = {"src_rgb",    "dst_rgb",        "equation_rgb", "src_alpha",
                                  "dst_alpha",  "equation_alpha", "func",         "ref",
                                  "value_mask", "fail",           "zfail",        "zpass",
                                  "write_mask", "texture",        "enabled"};

size_t part_rank(const std::string& key) {
    const auto* end = std::end(kPartOrder);
    return static_cast<size_t>(std::find(std::begin(kPartOrder), end, key) -
                               std::begin(kPartOrder));
}

bool is_draw(const std::string& call) {
    return (call.rfind("glDraw", 0) == 0 || call.rfind("glMultiDraw", 0) == 0);
}

// "Draw", "Dispatch", "Clear" or "Read-back": what the event is, to count it by.
std::string kind_of(const json& event) {
    const std::string call = event.value("call", "");
    if (is_draw(call)) return "Draw";
    if (call.rfind("glDispatch", 0) == 0) return "Dispatch";
    if (call.rfind("glClear", 0) == 0) return "Clear";
    return "Read-back";
}

// "Draw 2": the event's kind and its number among the events of that kind.
std::string event_name(const json& events, size_t index) {
    const std::string kind = kind_of(events[index]);
    int n = 0;
    for (size_t i = 0; i <= index; ++i) n += kind_of(events[i]) == kind;
    return kind + " " + std::to_string(n);
}

std::string scene_of(const fw::Checkpoint& cp) {
    if (cp.params.is_object() && cp.params.contains("scene") && cp.params["scene"].is_string())
        return "scene `" + cp.params["scene"].get<std::string>() + "`";
    return "checkpoint `" + cp.name + "`";
}

std::string value_text(const json* v) {
    if (!v) return "not set";
    if (v->is_string()) return v->get<std::string>();
    if (v->is_boolean()) return v->get<bool>() ? "GL_TRUE" : "GL_FALSE";
    std::string s = v->dump();
    return s.size() > 160 ? s.substr(0, 160) + "..." : s;
}

// The first path, in kOrder's order, where `a` and `b` differ; empty when
// they are equal. Objects compare key by key, arrays of numbers as a whole
// except the short ones that name parts (a box, a mask).
std::vector<std::string> first_difference(const json& a, const json& b,
                                          std::vector<std::string> path) {
    if (a == b) return {};
    if (a.is_object() && b.is_object()) {
        std::vector<std::string> keys;
        if (path.empty()) {
            for (const char* k : kOrder) keys.push_back(k);
            for (const auto& [k, v] : a.items())
                if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
            for (const auto& [k, v] : b.items())
                if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
        } else {
            for (const auto& [k, v] : a.items()) keys.push_back(k);
            for (const auto& [k, v] : b.items())
                if (!a.contains(k)) keys.push_back(k);
            std::stable_sort(keys.begin(), keys.end(),
                             [](const std::string& x, const std::string& y) {
                                 return part_rank(x) < part_rank(y);
                             });
        }
        for (const std::string& k : keys) {
            const bool in_a = a.contains(k), in_b = b.contains(k);
            if (!in_a && !in_b) continue;
            std::vector<std::string> here = path;
            here.push_back(k);
            if (in_a != in_b) return here;
            std::vector<std::string> d = first_difference(a[k], b[k], here);
            if (!d.empty()) return d;
        }
        return path;
    }
    const bool parts =
        !path.empty() && (path[0] == "viewport" || path[0] == "scissor" || path[0] == "color_mask");
    if (parts && a.is_array() && b.is_array() && a.size() == b.size()) {
        for (size_t i = 0; i < a.size(); ++i)
            if (a[i] != b[i]) {
                path.push_back(std::to_string(i));
                return path;
            }
    }
    return path;
}

const json* at_path(const json& event, const std::vector<std::string>& path) {
    const json* v = &event;
    for (const std::string& p : path) {
        if (v->is_object() && v->contains(p)) {
            v = &(*v)[p];
        } else if (v->is_array() && !p.empty() && std::all_of(p.begin(), p.end(), ::isdigit) &&
                   std::stoul(p) < v->size()) {
            v = &(*v)[std::stoul(p)];
        } else {
            return nullptr;
        }
    }
    return v;
}

// "GL_BLEND is not enabled (glEnable)" for a difference in the capabilities.
// `cap`: the capability's name.
std::string enabled_sentence(const json& student, const json& reference, std::string& cap) {
    for (const json& c : reference)
        if (std::find(student.begin(), student.end(), c) == student.end())
            return (cap = c.get<std::string>()) + " is not enabled (glEnable)";
    for (const json& c : student)
        if (std::find(reference.begin(), reference.end(), c) == reference.end())
            return (cap = c.get<std::string>()) +
                   " is enabled (glEnable), and changes what this draw does";
    return "";
}

// A part of the reference's state that the student's draw does not read:
// GL reads it only where other state asks for it. A texture's compare
// function is recorded only where its compare mode is on, so its absence
// is that mode left at GL_NONE.
std::string absent_sentence(const std::string& where, const std::string& gl,
                            const std::vector<std::string>& path) {
    const std::string func = "GL_TEXTURE_COMPARE_FUNC";
    if (path.size() == 3 && path[0] == "textures" && path[2] == "compare_func" &&
        gl.rfind(func, 0) == 0)
        return where + "GL_TEXTURE_COMPARE_MODE" + gl.substr(func.size()) +
               " is GL_NONE, so the texture is read without a comparison";
    return where + gl + " takes no part in this draw (GL reads it only where other state " +
           "asks for it)";
}

std::string with_words(std::string sentence, const std::string& words) {
    return sentence + (words.empty() ? "" : "; " + words) + ".";
}

std::string read_text_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The same events in another order (a sort's mistake): the sentence that
// names the first of the student's out of place; "" when the events differ
// or are the same in the same order.
std::string order_sentence(const json& s, const json& r, const std::string& scene,
                           const json& words, const fw::Checkpoint& cp) {
    std::vector<std::string> sd, rd;
    for (const json& e : s) sd.push_back(e.dump());
    for (const json& e : r) rd.push_back(e.dump());
    std::vector<std::string> ss = sd, rs = rd;
    std::sort(ss.begin(), ss.end());
    std::sort(rs.begin(), rs.end());
    if (ss != rs || sd == rd) return "";
    size_t i = 0;
    while (sd[i] == rd[i]) ++i;
    size_t j = i + 1;
    while (j < rd.size() && rd[j] != sd[i]) ++j;
    return with_words(event_name(s, i) + " of " + scene +
                          ": the draws come in another order: your " + event_name(s, i) +
                          " is the reference's " + event_name(r, j) +
                          " (the same state), drawn earlier than there",
                      sheet_words(words, {"order"}, cp));
}

}  // namespace

bool valid_record(const json& j) {
    return j.is_object() && j.value("version", 0) == fw::gl_record::kVersion &&
           j.contains("events") && j["events"].is_array();
}

std::string reference_record(const LabFiles& lab, const std::string& checkpoint) {
    return "labs/" + lab.dir + "/reference/" + checkpoint + ".record.json";
}

bool has_reference_record(const LabFiles& lab, const std::string& checkpoint) {
    return std::filesystem::is_regular_file(lab.root + "/" + reference_record(lab, checkpoint));
}

void check_reference_records(const LabFiles& lab) {
    for (const fw::Checkpoint& cp : lab.file.checkpoints) {
        if (!has_reference_record(lab, cp.name)) continue;
        const std::string rel = reference_record(lab, cp.name);
        const json record = json::parse(read_text_file(lab.root + "/" + rel), nullptr, false);
        if (!valid_record(record))
            throw fw::UsageError(rel + " is not a version " +
                                 std::to_string(fw::gl_record::kVersion) +
                                 " record of the draws; write it again: course bless " + lab.id);
    }
}

void write_reference_record(const LabFiles& lab, const std::string& checkpoint,
                            const std::string& text) {
    const std::string rel = reference_record(lab, checkpoint);
    const json record = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (!valid_record(record))
        throw fw::Error("the record of checkpoint '" + checkpoint + "' is not a version " +
                        std::to_string(fw::gl_record::kVersion) + " record; " + rel +
                        " is not written");
    std::ofstream out(lab.root + "/" + rel, std::ios::binary | std::ios::trunc);
    if (!(out << text) || !(out.close(), out)) throw fw::Error("cannot write '" + rel + "'");
}

std::string state_difference(const json& student, const json& reference, const fw::Checkpoint& cp,
                             const json& words, bool visible) {
    // Two drivers may keep different parts of a program active: compare
    // what both keep (record_match.hpp).
    json narrowed_student = student, narrowed_reference = reference;
    keep_common_interface(narrowed_student, narrowed_reference);
    const json& s = narrowed_student.at("events");
    const json& r = narrowed_reference.at("events");
    if (s == r) return "";
    const std::string scene = scene_of(cp);
    const std::string order = order_sentence(s, r, scene, words, cp);
    if (!order.empty()) return order;
    for (size_t i = 0; i < s.size() && i < r.size(); ++i) {
        if (s[i] == r[i]) continue;
        const std::string where = event_name(s, i) + " of " + scene + ": ";
        if (s[i].value("call", "") != r[i].value("call", "") && kind_of(s[i]) != kind_of(r[i]))
            return with_words(where + "you call " + s[i].value("call", "?") +
                                  " where the reference " + "makes its " + event_name(r, i),
                              "");
        const std::vector<std::string> path = first_difference(s[i], r[i], {});
        if (path.empty()) continue;
        const std::string sheet = sheet_words(words, path, cp);
        if (path[0] == "enabled" && path.size() == 1) {
            // The sheet's words for the capability: field "enabled.GL_BLEND".
            std::string cap;
            const std::string e = enabled_sentence(s[i]["enabled"], r[i]["enabled"], cap);
            if (!e.empty()) return with_words(where + e, sheet_words(words, {"enabled", cap}, cp));
        }
        const std::string gl = gl_words(path, s[i].value("call", ""));
        const json* mine = at_path(s[i], path);
        const json* theirs = at_path(r[i], path);
        std::string sentence = where + gl + " is " + value_text(mine);
        if (!mine) sentence = absent_sentence(where, gl, path);
        // A visible checkpoint's report shows the student's value and the
        // sheet's words, never the solution's own value (docs/contract.md).
        if (!visible) sentence += "; the reference's is " + value_text(theirs);
        return with_words(sentence, sheet);
    }
    if (s.size() != r.size()) {
        const size_t n = std::min(s.size(), r.size());
        if (s.size() > r.size())
            return with_words(scene + ": your " + event_name(s, n) + " (" +
                                  s[n].value("call", "?") + ") is one the reference does not make",
                              "");
        return with_words(scene + ": the reference's " + event_name(r, n) + " (" +
                              r[n].value("call", "?") + ") is missing from yours",
                          "");
    }
    return "";
}

json read_record(const std::string& path) {
    return json::parse(read_text_file(path), nullptr, /*allow_exceptions=*/false);
}

namespace {

// The sentence for two records, "" where they agree or are not records.
std::string difference_or_none(const json& student, const json& reference, const fw::Checkpoint& cp,
                               const json& words, bool visible) {
    try {
        return state_difference(student, reference, cp, words, visible);
    } catch (const json::exception&) {
        return "";  // a record that is not one record.hpp writes: nothing to say
    }
}

// For a guess that the frame is checkpoint `other`'s: whether the student's
// draws are that checkpoint's reference draws, where the two checkpoints'
// reference draws differ (CheckResult::FrameGuess::record_is_checkpoints).
int record_is_checkpoints(const LabFiles& lab, const fw::Checkpoint& cp, const std::string& other,
                          const json& student, const json& reference) {
    if (other.empty() || !has_reference_record(lab, other)) return 0;
    const json theirs = read_record(lab.root + "/" + reference_record(lab, other));
    if (!valid_record(theirs)) return 0;
    if (difference_or_none(reference, theirs, cp, json(), true).empty()) return 0;
    return difference_or_none(student, theirs, cp, json(), true).empty() ? 1 : -1;
}

}  // namespace

void add_state_diff(const LabFiles& lab, const fw::Checkpoint& cp, const ChildOutputs& outputs,
                    std::vector<CheckResult>& results) {
    CheckResult* first = nullptr;
    for (CheckResult& r : results)
        if (!r.passed && (r.kind == CheckKind::Image || r.kind == CheckKind::Probe ||
                          r.kind == CheckKind::Stat || r.kind == CheckKind::Buffer)) {
            first = &r;
            break;
        }
    if (!first || !has_reference_record(lab, cp.name)) return;
    std::string bytes, why;
    if (!outputs.read(cp.name + ".record.json", 16 * kMiB, bytes, why)) return;
    const json student = json::parse(bytes, nullptr, /*allow_exceptions=*/false);
    const json reference = read_record(lab.root + "/" + reference_record(lab, cp.name));
    // A student's record that is not one: the child did not write it (the
    // render failed, and its checks say why); course grade has checked the
    // reference's before grading.
    if (!valid_record(student) || !valid_record(reference)) return;
    const std::string sentence = difference_or_none(student, reference, cp, lab.state_words,
                                                    first->visibility == Visibility::Visible);
    // The evidence a guess from the frame is weighed against (frame_guesses.hpp).
    for (CheckResult& r : results) {
        if (r.guess.mistake_image.empty() && r.guess.checkpoint.empty()) continue;
        r.guess.state_compared = true;
        r.guess.state = sentence;
        r.guess.record_is_checkpoints =
            record_is_checkpoints(lab, cp, r.guess.checkpoint, student, reference);
    }
    // A state check of the checkpoint says it already.
    const bool said = std::any_of(results.begin(), results.end(), [](const CheckResult& r) {
        return r.kind == CheckKind::State && !r.passed;
    });
    if (sentence.empty() || said) return;
    first->diagnosis += (first->diagnosis.empty() ? "" : "\n") + sentence;
    first->output += "\n" + sentence;
}

}  // namespace grading
