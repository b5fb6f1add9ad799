// One interactive lab, as the window (`lab run`) and the browser page (`lab
// serve`) both drive it: the parameter values and everything that changes
// them (a value set by name, a checkpoint, the panel, a key: a parameter's
// shortcut, Shift for the other way, R to reload the shaders; a drag or a
// scroll through the lab's hooks), and the problems the user is shown. The
// frames themselves are LabRenderer's; the session says what to draw and
// keeps what went wrong.
//
// Not thread-safe: `lab serve` locks around it (framework/serve/live.hpp).
// The methods that call the lab (said so below) need whatever guards the lab
// object; apply_input() may compile shaders, so the GL context must be current.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/lab.hpp"
#include "framework/shortcuts.hpp"

namespace fw {

class LabRenderer;

// What the user is shown as wrong, until it is put right.
struct SessionProblems {
    // The programs that did not build: at the start, then as of the last reload.
    std::vector<std::string> shader_errors;
    // Why the newest frame was not drawn (parameters the lab rejects, a
    // draw that threw, a GL error); empty when it was drawn.
    std::string draw_error;
    // A drag or scroll that the lab's hook failed on, or whose result the
    // lab rejects (nothing changed then); empty once one is taken.
    std::string input_error;

    // As `lab serve` sends them (docs/contract.md, `lab serve`).
    nlohmann::json to_json() const;
    // As the window lists them: each with what to do about it, once.
    std::vector<std::string> lines() const;
};

class LabSession {
public:
    // Starts from `initial`, unchecked: a combination the lab rejects is
    // what the first frame reports. Works on the renderer's lab (validation,
    // hooks) and programs (reloads); the renderer must outlive it.
    LabSession(LabRenderer& renderer, ParamValues initial);

    const ParamValues& params() const { return params_; }
    const SessionProblems& problems() const { return problems_; }
    const LabInfo& info() const;

    // Changes made at once. Each is checked against the declaration and the
    // lab's validate() (a call of the lab) and throws UsageError naming what
    // is wrong; nothing changes then.
    void set(const std::string& name, const std::string& text);
    void load_checkpoint(const std::string& name);
    void replace(const ParamValues& values);  // the window's panel, reset to defaults
    // `key`: an upper-case ASCII letter or a digit. A parameter's shortcut
    // (`shift`: the other way; `repeat`: held down, when only numbers step
    // again), or R, which asks for a reload. False when the key does nothing
    // in this lab.
    bool press_key(int key, bool shift, bool repeat = false);
    // A key as a client names it: one letter or digit; throws UsageError for
    // anything else or a key that does nothing here, listing the lab's keys.
    void press_key(const std::string& key, bool shift);

    // Input kept for the next frame, in order; no call of the lab.
    void drag(double dx, double dy);  // frame pixels, dy > 0 upwards
    void scroll(double steps);
    void request_reload();

    // Before a frame: the shaders reloaded if asked, then the drags and
    // scrolls handed to the lab's hooks with `frame`. True when the shaders
    // were reloaded (then problems().shader_errors says how that went).
    bool apply_input(const Frame& frame);
    // After a frame: why it was not drawn, or empty when it was.
    void drawn(std::string error) { problems_.draw_error = std::move(error); }

    // The keys press_key takes: the parameters' shortcuts, then R.
    static std::vector<Shortcut> shortcuts(const LabInfo& info);

private:
    struct Motion {
        bool scroll = false;
        double dx = 0.0, dy = 0.0;  // a scroll's steps in dx
    };
    void commit(ParamValues next);
    void apply_motion(const Motion& motion, const Frame& frame);

    LabRenderer& renderer_;
    ParamValues params_;
    SessionProblems problems_;
    std::vector<Motion> motions_;
    bool reload_ = false;
};

}  // namespace fw
