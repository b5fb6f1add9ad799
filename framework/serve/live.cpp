#include "framework/serve/live.hpp"

#include <algorithm>
#include <exception>
#include <functional>

#include "framework/checkpoints.hpp"
#include "framework/error.hpp"
#include "framework/render.hpp"
#include "framework/session.hpp"

namespace fw {

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

// How often a playing lab is drawn, at most: the page's refresh rate.
constexpr std::chrono::milliseconds kPlayInterval{16};

json describe_lab(const RegisteredLab& lab, const ContextInfo& context) {
    json params = json::array(), shortcuts = json::array(), checkpoints = json::array();
    for (const Param& p : lab.info.params) params.push_back(describe_param(p));
    for (const Shortcut& s : LabSession::shortcuts(lab.info))
        shortcuts.push_back({{"keys", s.keys}, {"action", s.action}});
    for (const Checkpoint& cp : load_checkpoints(lab))
        checkpoints.push_back({{"name", cp.name},
                               {"description", cp.description},
                               {"visibility", cp.visibility},
                               {"params", checkpoint_params(lab, cp).to_json()}});
    return {{"lab", lab.info.id},
            {"number", lab.info.number},
            {"title", lab.info.title},
            {"params", params},
            {"controls", lab.info.controls},
            {"shortcuts", shortcuts},
            {"checkpoints", checkpoints},
            {"backend", context.backend},
            {"gl_version", context.gl_version},
            {"gl_renderer", context.gl_renderer},
            {"max_side", kMaxServeSide}};
}

bool animates(const ParamValues& params) { return params.declares(kAnimate) && params[kAnimate]; }

}  // namespace

LiveLab::LiveLab(const RegisteredLab& lab, Backend backend, int width, int height)
    : width_(width), height_(height), lab_(lab) {
    if (width < 1 || height < 1 || width > kMaxServeSide || height > kMaxServeSide)
        throw UsageError("--size " + std::to_string(width) + "x" + std::to_string(height) +
                         ": each side must be 1 to " + std::to_string(kMaxServeSide));
    std::exception_ptr failure;
    thread_ = std::thread([this, backend, &failure] {
        try {
            run(lab_, backend);
        } catch (...) {
            std::lock_guard<std::mutex> lock(mutex_);
            if (!started_) failure = std::current_exception();
            started_ = true;
            stopping_ = true;
            start_cv_.notify_all();
            framed_.notify_all();
        }
    });
    std::unique_lock<std::mutex> lock(mutex_);
    start_cv_.wait(lock, [this] { return started_; });
    if (failure) {
        lock.unlock();
        thread_.join();
        std::rethrow_exception(failure);
    }
}

LiveLab::~LiveLab() {
    stop();
    if (thread_.joinable()) thread_.join();
}

void LiveLab::stop() {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    wake_.notify_all();
    framed_.notify_all();
}

void LiveLab::run(const RegisteredLab& lab, Backend backend) {
    std::unique_ptr<OffscreenContext> context = create_offscreen_context(backend);
    LabRenderer renderer(lab, context->info());
    LabSession session(renderer, default_params(lab));
    json description = describe_lab(lab, context->info());
    {
        std::lock_guard<std::mutex> lock(mutex_);
        renderer_ = &renderer;
        session_ = &session;
        description_ = std::move(description);
        started_ = true;
        ++version_;  // the first frame
    }
    start_cv_.notify_all();
    try {
        render_loop();
    } catch (...) {
        detach();
        throw;
    }
    detach();
}

// The renderer and the session end with run(): nothing reaches them after.
void LiveLab::detach() {
    std::lock_guard<std::mutex> lock(mutex_);
    session_ = nullptr;
    renderer_ = nullptr;
}

bool LiveLab::await_change(Clock::time_point& next_due, double& time) {
    std::unique_lock<std::mutex> lock(mutex_);
    auto due = [this] { return stopping_ || version_ != drawn_version_; };
    const bool playing = players_ > 0 || animates(session_->params());
    if (playing)
        wake_.wait_until(lock, next_due, due);
    else
        wake_.wait(lock, due);
    next_due = std::max(next_due + kPlayInterval, Clock::now());
    if (stopping_) return false;
    time = playing ? std::chrono::duration<double>(Clock::now() - epoch_).count() : 0.0;
    return true;
}

// Called with lab_mutex_ held.
LiveLab::Job LiveLab::take_input(double time) {
    std::lock_guard<std::mutex> lock(mutex_);
    session_->apply_input(Frame{width_, height_, time});
    return {session_->params(), width_, height_, version_, time};
}

// Called with lab_mutex_ held.
std::shared_ptr<LiveFrame> LiveLab::draw(const Job& job) {
    auto frame = std::make_shared<LiveFrame>();
    try {
        RenderOutput out =
            renderer_->render(job.params, job.width, job.height, job.time, ReadBack{false, false});
        frame->render_ms = out.stats.value("render_ms", 0.0);
        frame->stats = std::move(out.stats);
        frame->jpeg = encode_jpeg(out.color, 85);
        frame->color = std::move(out.color);
    } catch (const std::exception& e) {
        // The last good frame stays on the page, with the reason beside it.
        std::lock_guard<std::mutex> lock(mutex_);
        if (frame_) *frame = *frame_;
        frame->error = e.what();
    }
    frame->params = job.params.to_json();
    frame->version = job.version;
    return frame;
}

void LiveLab::render_loop() {
    std::uint64_t seq = 0;
    Clock::time_point next_due = Clock::now();  // while playing: the next frame's start
    double time = 0.0;
    while (await_change(next_due, time)) {
        std::lock_guard<std::mutex> lab_lock(lab_mutex_);
        std::shared_ptr<LiveFrame> frame = draw(take_input(time));
        std::lock_guard<std::mutex> lock(mutex_);
        frame->seq = ++seq;
        session_->drawn(frame->error);
        drawn_version_ = frame->version;
        frame_ = std::move(frame);
        framed_.notify_all();
    }
}

std::uint64_t LiveLab::change(const std::function<void(LabSession&)>& use) {
    std::lock_guard<std::mutex> lab_lock(lab_mutex_);
    return with_session(use);
}

std::uint64_t LiveLab::with_session(const std::function<void(LabSession&)>& use) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!session_) throw Error("the lab is not running");
    use(*session_);
    wake_.notify_all();
    return ++version_;
}

std::uint64_t LiveLab::set(const std::string& name, const std::string& value) {
    return change([&](LabSession& s) { s.set(name, value); });
}

std::uint64_t LiveLab::load_checkpoint(const std::string& name) {
    return change([&](LabSession& s) { s.load_checkpoint(name); });
}

std::uint64_t LiveLab::key(const std::string& key, bool shift) {
    return change([&](LabSession& s) { s.press_key(key, shift); });
}

std::uint64_t LiveLab::drag(double dx, double dy) {
    return with_session([&](LabSession& s) { s.drag(dx, dy); });
}

std::uint64_t LiveLab::scroll(double steps) {
    return with_session([&](LabSession& s) { s.scroll(steps); });
}

std::uint64_t LiveLab::reload_shaders() {
    return with_session([](LabSession& s) { s.request_reload(); });
}

std::uint64_t LiveLab::redraw() {
    std::lock_guard<std::mutex> lock(mutex_);
    wake_.notify_all();
    return ++version_;
}

std::uint64_t LiveLab::resize(int width, int height) {
    if (width < 16 || height < 16 || width > kMaxServeSide || height > kMaxServeSide)
        throw UsageError("size " + std::to_string(width) + "x" + std::to_string(height) +
                         ": each side must be 16 to " + std::to_string(kMaxServeSide));
    std::lock_guard<std::mutex> lock(mutex_);
    if (width == width_ && height == height_) return version_;
    width_ = width;
    height_ = height;
    wake_.notify_all();
    return ++version_;
}

std::uint64_t LiveLab::play(bool on) {
    std::lock_guard<std::mutex> lock(mutex_);
    players_ = std::max(0, players_ + (on ? 1 : -1));
    wake_.notify_all();
    return ++version_;
}

std::shared_ptr<const LiveFrame> LiveLab::wait_frame(std::uint64_t after,
                                                     std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    framed_.wait_for(lock, timeout, [&] { return stopping_ || (frame_ && frame_->seq > after); });
    return frame_ && frame_->seq > after ? frame_ : nullptr;
}

std::shared_ptr<const LiveFrame> LiveLab::latest() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return frame_;
}

json LiveLab::problems() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return session_ ? session_->problems().to_json() : SessionProblems{}.to_json();
}

}  // namespace fw
