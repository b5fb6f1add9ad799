// `lab serve` (docs/contract.md, `lab serve`) in a real browser: headless
// Chromium (tests/support/browser.hpp) loads the page of a real `lab serve`
// child, moves a slider and picks a choice through the page's own controls,
// drags on the frame, and presses R with a broken shader on disk. Frames are
// compared, pixel for pixel within the graders' fuzzy threshold, with what
// `lab render` draws with the same parameters. The server is also attacked
// with raw requests (paths with "..", bad values, bad messages), a client
// that stops reading, and SIGTERM. Runs once per offscreen backend; leaves a
// screenshot of the page for every lab in build/test-out/.
#include <signal.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <thread>

#include "framework/image.hpp"
#include "framework/text.hpp"
#include "tests/support/browser.hpp"
#include "tests/support/test_support.hpp"
#include "tests/tools/serve_support.hpp"

namespace fs = std::filesystem;
using fw::test::Browser;
using nlohmann::json;
using serve_test::Served;

namespace {

// Waits until the JavaScript expression `condition` is true in the page (30 s
// at most) and returns the value of `value` then; `what` names the wait in
// the failure.
json wait_for(Browser& browser, const std::string& condition, const std::string& value,
              const std::string& what) {
    const std::string js =
        "new Promise((ok, fail) => { const t0 = Date.now(); (function poll() { let done = false;"
        " try { done = (" +
        condition + "); } catch (e) {} if (done) ok(" + value +
        "); else if (Date.now() - t0 > 30000) fail(new Error(" +
        json("timed out waiting for " + what + "; status: ").dump() +
        " + document.getElementById('status').textContent)); else setTimeout(poll, 20); })(); })";
    return browser.evaluate(js);
}

fw::Image png_from_data_url(const std::string& url) {
    const std::string prefix = "data:image/png;base64,";
    REQUIRE(url.rfind(prefix, 0) == 0);
    return fw::decode_png(fw::test::base64_decode(url.substr(prefix.size())), "the page's canvas");
}

// The frame on the page's canvas, as pixels.
fw::Image canvas_pixels(Browser& browser) {
    return png_from_data_url(
        browser.evaluate("document.getElementById('frame').toDataURL('image/png')"));
}

// `lab render LAB --set ... --size WxH` of the parameters the page's newest
// frame was drawn with.
fw::Image lab_render(const std::string& lab, const json& meta, const std::string& env) {
    std::string sets;
    for (const auto& [name, value] : meta["params"].items())
        sets += " --set " +
                fw::shell_quote(name + "=" +
                                (value.is_string() ? value.get<std::string>() : value.dump()));
    const std::string png = fw::test::out_dir() + "/lab_render.png";
    const fw::test::CommandResult r =
        fw::test::run_command(env + " " + fw::test::bin_dir() + "/lab render " + lab + sets +
                              " --size " + std::to_string(meta["width"].get<int>()) + "x" +
                              std::to_string(meta["height"].get<int>()) + " -o " + png);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return fw::read_png(png);
}

// The page's newest frame matches `lab render` with its parameters, within
// the fuzzy threshold course grade uses for references.
void check_frame_matches_lab_render(Browser& browser, const std::string& lab,
                                    const std::string& env, const std::string& what) {
    // Every change the page sent answered, and drawn: then the frame and
    // its parameters, read together.
    const json shown = wait_for(
        browser, "labServe.unanswered === 0 && labServe.meta.version >= labServe.acked",
        "({meta: labServe.meta, png: document.getElementById('frame').toDataURL('image/png')})",
        "the frame of the last change");
    const json& meta = shown["meta"];
    REQUIRE(meta["format"] == "png");
    const fw::Image page = png_from_data_url(shown["png"]);
    const fw::Image rendered = lab_render(lab, meta, env);
    const fw::CompareResult c = fw::compare_images(page, rendered, fw::CompareOptions{});
    INFO(what << ": page frame " << page.width << "x" << page.height
              << " vs lab render: " << c.summary());
    CHECK(c.passed);
}

// A lab's page up and showing frames as PNG (exact pixels).
void open_page(Browser& browser, const Served& served) {
    browser.navigate(served.url());
    wait_for(browser, "labServe.frames >= 1 && labServe.lab", "true", "the first frame");
    browser.evaluate("labServe.send({type: 'format', format: 'png'})");
    wait_for(browser, "labServe.meta && labServe.meta.format === 'png'", "true", "a PNG frame");
}

std::string shader_env(const std::string& dir) { return "LAB_SHADER_DIR=" + dir; }

}  // namespace

TEST_CASE("lab serve: slider, choice, drag and R with a broken shader, in a real browser") {
    fw::test::chromium_or_skip();
    const std::string shaders = fw::test::out_dir() + "/shaders";
    fs::remove_all(shaders);
    fs::copy(fw::test::source_dir() + "/shaders", shaders, fs::copy_options::recursive);
    Served served({"pipeline", "--size", "320x240"}, {shader_env(shaders)});
    Browser browser(fw::test::out_dir() + "/chromium.log", 1100, 700);
    open_page(browser, served);
    const json described = browser.evaluate("labServe.lab.params.map(p => p.name)");
    CHECK(described ==
          json({"scene", "depth_test", "first", "storage", "primitive", "cull", "yaw", "pitch"}));

    // A choice, through the page's own <select>.
    browser.evaluate(
        "(() => { const s = document.getElementById('param-scene'); s.value = 'culling'; "
        "s.dispatchEvent(new Event('change')); })()");
    wait_for(browser, "labServe.meta.params.scene === 'culling'", "true", "scene=culling");
    check_frame_matches_lab_render(browser, "pipeline", shader_env(shaders), "scene culling");

    // A slider, through the page's own range input.
    const double yaw = browser.evaluate(
        "(() => { const s = document.getElementById('param-yaw'); s.value = '-60'; "
        "s.dispatchEvent(new Event('input')); return Number(s.value); })()");
    wait_for(browser, "Math.abs(labServe.meta.params.yaw - (" + std::to_string(yaw) + ")) < 1e-3",
             "true", "the slider's yaw");
    check_frame_matches_lab_render(browser, "pipeline", shader_env(shaders), "yaw slider");
    const fw::Image before_drag = canvas_pixels(browser);

    // A drag on the frame turns the cube (the lab's on_drag changes yaw).
    const json box = browser.evaluate(
        "(() => { const r = document.getElementById('frame').getBoundingClientRect(); "
        "return {x: r.left + r.width / 2, y: r.top + r.height / 2}; })()");
    const double x = box["x"], y = box["y"];
    browser.call("Input.dispatchMouseEvent", {{"type", "mousePressed"},
                                              {"x", x},
                                              {"y", y},
                                              {"button", "left"},
                                              {"buttons", 1},
                                              {"clickCount", 1}});
    for (int i = 1; i <= 5; ++i)
        browser.call("Input.dispatchMouseEvent", {{"type", "mouseMoved"},
                                                  {"x", x + 12 * i},
                                                  {"y", y},
                                                  {"button", "left"},
                                                  {"buttons", 1}});
    browser.call("Input.dispatchMouseEvent", {{"type", "mouseReleased"},
                                              {"x", x + 60},
                                              {"y", y},
                                              {"button", "left"},
                                              {"clickCount", 1}});
    const double dragged =
        wait_for(browser, "Math.abs(labServe.meta.params.yaw - (" + std::to_string(yaw) + ")) > 5",
                 "labServe.meta.params.yaw", "the drag to turn the cube");
    INFO("yaw " << yaw << " -> " << dragged << " after the drag");
    CHECK(dragged > yaw);
    CHECK(fw::compare_images(canvas_pixels(browser), before_drag, fw::CompareOptions{}).passed ==
          false);
    check_frame_matches_lab_render(browser, "pipeline", shader_env(shaders), "after the drag");
    CHECK(browser.evaluate("document.getElementById('param-yaw').value").get<std::string>() !=
          "-60");

    // R with a shader that does not compile: the error shows, the last good
    // program keeps drawing; fixed on disk, R again clears it.
    const std::string frag = shaders + "/00_pipeline/pipeline.frag";
    const std::string good = fw::test::read_text(frag);
    fw::test::write_text(frag, good + "\nthis is not GLSL;\n");
    auto press_r = [&] {
        browser.call("Input.dispatchKeyEvent", {{"type", "keyDown"},
                                                {"key", "r"},
                                                {"code", "KeyR"},
                                                {"windowsVirtualKeyCode", 82},
                                                {"text", "r"}});
        browser.call(
            "Input.dispatchKeyEvent",
            {{"type", "keyUp"}, {"key", "r"}, {"code", "KeyR"}, {"windowsVirtualKeyCode", 82}});
    };
    press_r();
    const std::string shown =
        wait_for(browser, "!document.getElementById('problems').hidden",
                 "document.getElementById('problems').textContent", "the shader error on the page");
    fw::test::check_mentions(shown, {"pipeline.frag"});
    check_frame_matches_lab_render(browser, "pipeline",
                                   shader_env(fw::test::source_dir() + "/shaders"),
                                   "the last good program, still drawing");
    fw::test::write_text(frag, good);
    press_r();
    wait_for(browser, "document.getElementById('problems').hidden", "true",
             "the shader error to clear");
    CHECK_MESSAGE(browser.page_errors().empty(), fw::join(browser.page_errors(), "\n"));
}

TEST_CASE(
    "lab serve: bad requests get a 400 or an error message naming the problem, and it serves on") {
    Served served({"pipeline", "--size", "64x64"});
    using serve_test::http_raw;
    using serve_test::status_of;
    const int port = served.port();
    auto get = [&](const std::string& target) {
        return http_raw(
            port, "GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
    };
    auto post = [&](const std::string& target) {
        return http_raw(port,
                        "POST " + target +
                            " HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 0\r\nConnection: "
                            "close\r\n\r\n");
    };
    CHECK(status_of(get("/")) == 200);
    CHECK(status_of(get("/serve.js")) == 200);
    for (const char* target :
         {"/../../../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd", "/..%2f..%2fetc%2fpasswd",
          "//etc/passwd", "/serve.js/../../../etc/passwd", "/etc/passwd", "/lab.cpp"}) {
        const std::string r = get(target);  // sent as written: no client tidies it
        INFO(std::string(target) << " -> " << r);
        CHECK(status_of(r) == 404);
        CHECK(r.find("root:") == std::string::npos);
    }
    CHECK(status_of(get("http://127.0.0.1/etc/passwd")) != 200);
    const std::string unknown = post("/api/set?colour=red");
    CHECK(status_of(unknown) == 400);
    fw::test::check_mentions(unknown, {"no parameter 'colour'", "yaw"});
    const std::string range = post("/api/set?yaw=1000");
    CHECK(status_of(range) == 400);
    fw::test::check_mentions(range, {"yaw", "1000"});
    const std::string nan = post("/api/set?yaw=abc");
    CHECK(status_of(nan) == 400);
    fw::test::check_mentions(nan, {"yaw", "abc"});
    CHECK(status_of(post("/api/set?scene=indexed")) == 200);
    CHECK(status_of(get("/api/set?scene=indexed")) == 405);
    CHECK(status_of(get("/frame.png")) == 200);

    if (!fw::test::chromium_path().empty()) {
        Browser browser(fw::test::out_dir() + "/chromium-bad.log", 800, 600);
        browser.navigate(served.url());
        wait_for(browser, "labServe.frames >= 1", "true", "the first frame");
        const std::vector<std::pair<std::string, std::string>> bad = {
            {"{type: 'size', width: 5, height: 99999}", "16 to 2048"},
            {"{type: 'set', name: 'pitch', value: 'x'}", "pitch"},
            {"{type: 'warp'}", "unknown message type"},
            {"{type: 'key', key: 'Q'}", "does nothing"},
            {"{type: 'drag', dx: 'far', dy: 1}", "dx"},
        };
        for (const auto& [message, needle] : bad) {
            browser.evaluate("labServe.lastError = ''");
            browser.evaluate("labServe.send(" + message + ")");
            const std::string error =
                wait_for(browser, "labServe.lastError !== ''", "labServe.lastError", message);
            INFO(message);
            fw::test::check_mentions(error, {needle});
        }
        browser.evaluate("labServe.lastError = ''");
        browser.evaluate("labServe.socket.send('{not json')");
        const std::string error = wait_for(browser, "labServe.lastError !== ''",
                                           "labServe.lastError", "the malformed message");
        fw::test::check_mentions(error, {"JSON object"});
    }
    CHECK(status_of(get("/")) == 200);  // still serving
    std::string output;
    const int status = served.stop(SIGTERM, output);
    INFO(output);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
    fw::test::check_mentions(output, {"terminated, stopping"});
}

TEST_CASE("lab serve: a client that stops reading holds up nobody else") {
    fw::test::chromium_or_skip();
    Served served({"pipeline", "--size", "400x300"});
    Browser browser(fw::test::out_dir() + "/chromium-slow.log", 800, 600);
    browser.navigate(served.url());
    wait_for(browser, "labServe.frames >= 1", "true", "the first frame");
    const int stalled = serve_test::stalled_websocket(served.port());
    REQUIRE(stalled >= 0);
    browser.evaluate("labServe.send({type: 'play', on: true})");
    std::this_thread::sleep_for(std::chrono::seconds(1));  // the stalled client's buffers fill
    const int before = browser.evaluate("labServe.frames");
    std::this_thread::sleep_for(std::chrono::seconds(2));
    const int after = browser.evaluate("labServe.frames");
    INFO("frames in 2 s beside a client that reads nothing: " << after - before);
    CHECK(after - before >= 10);
    CHECK(serve_test::status_of(serve_test::http_raw(
              served.port(), "GET /api/lab HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")) ==
          200);
    close(stalled);
    std::string output;
    const int status = served.stop(SIGINT, output);
    INFO(output);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
}

TEST_CASE("lab serve: every lab's page, with its panel and a frame, screenshotted") {
    fw::test::chromium_or_skip();
    const fw::test::CommandResult list =
        fw::test::run_command(fw::test::bin_dir() + "/lab list --json");
    REQUIRE(list.exit_code == 0);
    const json labs = json::parse(list.output);
    REQUIRE(labs.size() >= 7);
    for (const json& lab : labs) {
        const std::string id = lab["name"];
        CAPTURE(id);
        Served served({id});
        Browser browser(fw::test::out_dir() + "/chromium-" + id + ".log", 1200, 700);
        open_page(browser, served);
        const size_t controls =
            browser.evaluate("document.querySelectorAll('#params .param').length");
        CHECK(controls == lab["params"].size());
        check_frame_matches_lab_render(browser, id, "", "the default parameters");
        browser.screenshot(fw::test::out_dir() + "/page-" + id + ".png");
        CHECK_MESSAGE(browser.page_errors().empty(), fw::join(browser.page_errors(), "\n"));
    }
}
