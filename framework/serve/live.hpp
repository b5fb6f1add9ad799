// A lab rendered live for `lab serve`: one offscreen context and renderer on
// a thread of their own, re-rendering when the parameters, the frame size or
// the shaders change (or every frame while the lab animates or a client plays
// it), and the latest frame kept for whoever asks. The parameters, the input
// and the problems are a LabSession's (framework/session.hpp), locked here.
// Transport-free: the HTTP and WebSocket side (server.cpp) only calls these
// methods.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "framework/context.hpp"
#include "framework/image.hpp"
#include "framework/lab.hpp"

namespace fw {

class LabRenderer;
class LabSession;

// The largest frame a page may ask for, each side.
constexpr int kMaxServeSide = 2048;

struct LiveFrame {
    std::uint64_t seq = 0;      // 1, 2, ... in the order rendered
    std::uint64_t version = 0;  // the change it shows all of (see LiveLab::version)
    Image color;
    std::string jpeg;  // encoded once, for every client
    double render_ms = 0.0;
    nlohmann::json stats;   // lab render's --stats fields
    nlohmann::json params;  // the values it was drawn with
    // Why the newest change could not be drawn (then this is the last good
    // frame); empty when it was.
    std::string error;
};

class LiveLab {
public:
    // Starts the render thread, which creates the context on `backend` and
    // the lab; throws what that throws (no context, a lab whose init fails).
    LiveLab(const RegisteredLab& lab, Backend backend, int width, int height);
    ~LiveLab();
    LiveLab(const LiveLab&) = delete;
    LiveLab& operator=(const LiveLab&) = delete;

    // The lab for the page: title, parameter declarations (names, types,
    // ranges, steps, units, help, choices, keys), controls, shortcuts,
    // checkpoints with their parameters, the GL renderer.
    const nlohmann::json& describe() const { return description_; }

    // Each change is validated first and throws UsageError naming what is
    // wrong (nothing changes then); it returns the version that the first
    // frame showing it will carry.
    std::uint64_t set(const std::string& name, const std::string& value);
    std::uint64_t load_checkpoint(const std::string& name);
    std::uint64_t drag(double dx, double dy);  // frame pixels, dy > 0 upwards
    std::uint64_t scroll(double steps);
    std::uint64_t key(const std::string& key, bool shift);  // a letter or digit; R reloads
    std::uint64_t reload_shaders();
    std::uint64_t resize(int width, int height);
    std::uint64_t play(bool on);  // re-render every frame, time running, until off
    std::uint64_t redraw();       // the same parameters drawn again

    // The newest frame once its seq is above `after`, or null after `timeout`
    // or once stopping.
    std::shared_ptr<const LiveFrame> wait_frame(std::uint64_t after,
                                                std::chrono::milliseconds timeout);
    std::shared_ptr<const LiveFrame> latest() const;
    // The session's problems (docs/contract.md, `lab serve`): shader build
    // errors, why the newest change could not be drawn, a drag or scroll the
    // lab could not take.
    nlohmann::json problems() const;
    // Wakes every waiter and ends the render thread.
    void stop();

private:
    void run(const RegisteredLab& lab, Backend backend);
    void render_loop();
    // The render thread's steps: wait until something is to be drawn (false:
    // stopping), with the lab's time when it animates; hand the input that
    // came meanwhile to the lab and take what to draw; draw it.
    struct Job {
        ParamValues params;
        int width = 0, height = 0;
        std::uint64_t version = 0;
        double time = 0.0;
    };
    bool await_change(std::chrono::steady_clock::time_point& next_due, double& time);
    Job take_input(double time);
    std::shared_ptr<LiveFrame> draw(const Job& job);
    // Calls `use` on the session under mutex_ and wakes the render thread;
    // returns the version that shows it. change() also holds lab_mutex_, for
    // what calls the lab (validation); input kept for the next frame does not.
    std::uint64_t change(const std::function<void(LabSession&)>& use);
    std::uint64_t with_session(const std::function<void(LabSession&)>& use);
    void detach();

    mutable std::mutex mutex_;
    std::condition_variable wake_;    // the render thread: something changed
    std::condition_variable framed_;  // waiters: a new frame
    std::uint64_t version_ = 0, drawn_version_ = 0;
    int width_, height_;
    int players_ = 0;
    bool stopping_ = false;
    std::shared_ptr<const LiveFrame> frame_;

    // Set up by the render thread before the constructor returns, and
    // cleared (under mutex_) before the objects they point to end with it.
    std::mutex lab_mutex_;  // the lab object: draws, drags and validation
    LabRenderer* renderer_ = nullptr;
    LabSession* session_ = nullptr;  // the parameters, input and problems
    nlohmann::json description_;
    std::string start_error_;
    bool started_ = false;
    std::condition_variable start_cv_;
    std::chrono::steady_clock::time_point epoch_ = std::chrono::steady_clock::now();
    const RegisteredLab& lab_;
    std::thread thread_;
};

}  // namespace fw
