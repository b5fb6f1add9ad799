#include "framework/session.hpp"

#include <algorithm>
#include <cctype>
#include <exception>
#include <utility>

#include "framework/checkpoints.hpp"
#include "framework/error.hpp"
#include "framework/render.hpp"
#include "framework/text.hpp"

namespace fw {

nlohmann::json SessionProblems::to_json() const {
    return {{"shader_errors", shader_errors},
            {"render_error", draw_error},
            {"input_error", input_error}};
}

std::vector<std::string> SessionProblems::lines() const {
    std::vector<std::string> lines;
    for (const std::string& e : shader_errors)
        lines.push_back(
            "A shader did not build; a program that built before keeps drawing. Fix the file and "
            "press R.\n" +
            e);
    // A program that never built fails the draw with its build error: said once.
    const bool known =
        std::find(shader_errors.begin(), shader_errors.end(), draw_error) != shader_errors.end();
    if (!draw_error.empty() && !known) lines.push_back("Drawing failed: " + draw_error);
    if (!input_error.empty()) lines.push_back(input_error);
    return lines;
}

LabSession::LabSession(LabRenderer& renderer, ParamValues initial)
    : renderer_(renderer), params_(std::move(initial)) {
    for (const ShaderError* e : renderer_.programs().build_errors())
        problems_.shader_errors.push_back(e->what());
}

const LabInfo& LabSession::info() const { return renderer_.registered().info; }

void LabSession::commit(ParamValues next) {
    const std::string problem = renderer_.lab().validate(next);
    if (!problem.empty()) throw UsageError("lab '" + info().id + "': " + problem);
    params_ = std::move(next);
}

void LabSession::set(const std::string& name, const std::string& text) {
    ParamValues next = params_;
    next.set(name, text);
    commit(std::move(next));
}

void LabSession::load_checkpoint(const std::string& name) {
    const RegisteredLab& lab = renderer_.registered();
    const std::vector<Checkpoint> all = load_checkpoints(lab);
    commit(checkpoint_params(lab, find_checkpoint(all, name, info().id)));
}

void LabSession::replace(const ParamValues& values) { commit(values); }

bool LabSession::press_key(int key, bool shift, bool repeat) {
    if (key == 'R') {
        if (!repeat) request_reload();
        return true;
    }
    const std::vector<Param>& params = info().params;
    const bool known = std::any_of(params.begin(), params.end(), [&](const Param& p) {
        return p.shortcut != 0 && std::toupper(p.shortcut) == key;
    });
    if (!known) return false;
    ParamValues next = params_;
    if (apply_param_key(next, key, shift, repeat)) commit(std::move(next));
    return true;
}

void LabSession::press_key(const std::string& key, bool shift) {
    if (key.size() != 1 || !std::isalnum(static_cast<unsigned char>(key[0])))
        throw UsageError("key '" + key + "': keys are one letter or digit");
    if (!press_key(std::toupper(static_cast<unsigned char>(key[0])), shift))
        throw UsageError("key '" + key + "' does nothing in lab '" + info().id +
                         "'; its keys: " + join(shortcuts(info()), ", ", &Shortcut::keys));
}

void LabSession::drag(double dx, double dy) { motions_.push_back({false, dx, dy}); }

void LabSession::scroll(double steps) { motions_.push_back({true, steps, 0.0}); }

void LabSession::request_reload() { reload_ = true; }

void LabSession::apply_motion(const Motion& motion, const Frame& frame) {
    ParamValues next = params_;
    try {
        Lab& lab = renderer_.lab();
        const bool changed = motion.scroll ? lab.on_scroll(next, frame, motion.dx)
                                           : lab.on_drag(next, frame, motion.dx, motion.dy);
        if (changed) commit(std::move(next));
        problems_.input_error.clear();
    } catch (const std::exception& e) {
        problems_.input_error = std::string("The lab could not take a ") +
                                (motion.scroll ? "scroll" : "drag") + ": " + e.what();
    }
}

bool LabSession::apply_input(const Frame& frame) {
    const bool reload = std::exchange(reload_, false);
    if (reload) problems_.shader_errors = renderer_.programs().reload_all();
    const Frame scene = scene_frame(renderer_.registered().info, frame);
    for (const Motion& motion : motions_) apply_motion(motion, scene);
    motions_.clear();
    return reload;
}

std::vector<Shortcut> LabSession::shortcuts(const LabInfo& info) {
    std::vector<Shortcut> list = param_shortcuts(info);
    list.push_back({"R", "reload shaders from disk"});
    return list;
}

}  // namespace fw
