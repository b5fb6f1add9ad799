// Headless Chromium over the DevTools protocol's pipe (browser.hpp).
#include "tests/support/browser.hpp"

#include <doctest/doctest.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <thread>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "tests/support/test_support.hpp"

namespace fw::test {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

namespace {

// A reply or event may take this long: llvmpipe-free, but a long page's
// screenshot on a loaded two-core machine is slow.
constexpr auto kTimeout = std::chrono::seconds(60);

std::string on_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    for (size_t begin = 0; begin <= dirs.size();) {
        size_t end = dirs.find(':', begin);
        if (end == std::string::npos) end = dirs.size();
        const std::string candidate = dirs.substr(begin, end - begin) + "/" + name;
        if (end > begin && access(candidate.c_str(), X_OK) == 0) return candidate;
        begin = end + 1;
    }
    return "";
}

// JavaScript: the violations of a page, as axe-core would find them at WCAG
// 2 AA for the rules the course's pages could break (Debian packages no
// axe-core, so they are checked here by script): each [rule, target, what].
// - color-contrast: each text node's colour against the background behind it
//   (the first opaque one among its ancestors, translucent ones blended over
//   it), WCAG's contrast ratio of relative luminances, 4.5:1 (3:1 for large
//   text: 24px, or 18.66px bold);
// - empty-table-header: every <th> has text (visually hidden text counts);
//   table-header: every <table> has a <th>;
// - heading-order: a heading is at most one level below the one before it;
//   page-has-heading-one: there is an <h1>;
// - image-alt: every <img> has alt text; svg-img-alt and role-img-alt: every
//   element of role img (an inline <svg> too) has a name, by aria-label or
//   by aria-labelledby naming elements with text;
// - landmark-one-main: exactly one <main>;
// - region: every text node is inside a landmark (main, nav, aside, a header
//   or footer of the body, or an element with a landmark role);
// - duplicate-id: no id used twice (which the HTML checker refuses too).
const char* const kAccessibilityJs = R"JS((() => {
  const target = e => { const p = []; for (; e && e !== document.body; e = e.parentElement) {
      if (e.id) { p.unshift('#' + e.id); break; }
      p.unshift(e.tagName.toLowerCase() + (e.className ? '.' + [...e.classList].join('.') : ''));
    } return p.join(' > '); };
  const rgba = c => { const m = c.match(/[\d.]+/g).map(Number); return [m[0], m[1], m[2], m.length > 3 ? m[3] : 1]; };
  const lin = v => { v /= 255; return v <= 0.04045 ? v / 12.92 : Math.pow((v + 0.055) / 1.055, 2.4); };
  const luminance = c => 0.2126 * lin(c[0]) + 0.7152 * lin(c[1]) + 0.0722 * lin(c[2]);
  const over = (top, under) => [0, 1, 2].map(i => top[i] * top[3] + under[i] * (1 - top[3])).concat(1);
  const background = e => { const layers = [];
    for (; e; e = e.parentElement) { const c = rgba(getComputedStyle(e).backgroundColor);
      if (c[3] > 0) layers.push(c); if (c[3] >= 1) break; }
    return layers.reverse().reduce((under, top) => over(top, under), [255, 255, 255, 1]); };
  const out = [];
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  let texts = 0;
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    if (!n.textContent.trim()) continue;
    const e = n.parentElement, s = getComputedStyle(e);
    if (s.display === 'none' || s.visibility === 'hidden') continue;
    ++texts;
    const bg = background(e), fg = over(rgba(s.color), bg);
    const l1 = luminance(fg), l2 = luminance(bg);
    const ratio = (Math.max(l1, l2) + 0.05) / (Math.min(l1, l2) + 0.05);
    const size = parseFloat(s.fontSize), large = size >= 24 || (size >= 18.66 && +s.fontWeight >= 700);
    if (ratio < (large ? 3 : 4.5))
      out.push(['color-contrast', target(e), ratio.toFixed(2) + ':1, ' + s.color + ' on rgb(' + bg.slice(0, 3) + ')']);
    if (!e.closest('main, nav, aside, body > header, body > footer, [role=main], [role=navigation], ' +
                   '[role=banner], [role=contentinfo], [role=complementary], [role=region], [role=search]'))
      out.push(['region', target(e), 'text outside every landmark: ' + n.textContent.trim().slice(0, 40)]);
  }
  document.querySelectorAll('th').forEach(th => { if (!th.textContent.trim())
    out.push(['empty-table-header', target(th), 'a table header without text']); });
  document.querySelectorAll('table').forEach(t => { if (!t.querySelector('th'))
    out.push(['table-header', target(t), 'a table without a header cell']); });
  let level = 0, ones = 0;
  document.querySelectorAll('h1, h2, h3, h4, h5, h6').forEach(h => { const l = +h.tagName[1];
    if (l > level + 1) out.push(['heading-order', target(h), 'h' + l + ' after h' + level]);
    level = l; ones += l === 1; });
  if (ones === 0) out.push(['page-has-heading-one', 'body', 'no h1']);
  const named = e => { const by = e.getAttribute('aria-labelledby');
    const text = (by ? by.split(/\s+/).map(id => document.getElementById(id))
                          .map(l => l ? l.textContent : '').join(' ') : '') +
                 (e.getAttribute('aria-label') || '');
    return text.trim() !== ''; };
  document.querySelectorAll('img').forEach(i => { if (!i.hasAttribute('alt'))
    out.push(['image-alt', target(i), 'an image without alt text']); });
  document.querySelectorAll('[role=img]').forEach(i => { if (!named(i))
    out.push([i.tagName.toLowerCase() === 'svg' ? 'svg-img-alt' : 'role-img-alt', target(i),
              'an image without a name (aria-label or aria-labelledby)']); });
  const mains = document.querySelectorAll('main, [role=main]').length;
  if (mains !== 1) out.push(['landmark-one-main', 'body', mains + ' main landmarks']);
  const ids = {};
  document.querySelectorAll('[id]').forEach(e => { if (ids[e.id]) out.push(['duplicate-id', '#' + e.id, 'id used twice']); ids[e.id] = 1; });
  return {texts, violations: out};
})())JS";

}  // namespace

std::string chromium_path() {
    if (const char* chosen = std::getenv("LAB_CHROMIUM"); chosen && *chosen) return chosen;
    for (const char* name : {"chromium", "chromium-browser", "google-chrome"})
        if (std::string found = on_path(name); !found.empty()) return found;
    return "";
}

namespace {

const char* const kNoChromium =
    "no Chromium: scripts/test.sh installs Debian's chromium package (or set LAB_CHROMIUM)";

bool browser_required() {
    const char* require = std::getenv("LAB_REQUIRE_BROWSER");
    return require && std::string(require) == "1";
}

}  // namespace

std::string chromium_or_skip() {
    std::string path = chromium_path();
    if (!path.empty()) return path;
    if (browser_required()) {
        FAIL(kNoChromium << "; LAB_REQUIRE_BROWSER=1 asks for it");
        return "";
    }
    std::printf("SKIP: %s\n", kNoChromium);
    std::fflush(stdout);
    std::_Exit(77);
}

bool chromium_for_case() {
    if (!chromium_path().empty()) return true;
    if (browser_required()) FAIL(kNoChromium << "; LAB_REQUIRE_BROWSER=1 asks for it");
    MESSAGE("SKIP this case: " << kNoChromium);
    return false;
}

std::string base64_decode(const std::string& text) {
    const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    unsigned bits = 0, value = 0;
    for (char c : text) {
        if (c == '=') break;
        const size_t digit = alphabet.find(c);
        if (digit == std::string::npos)
            throw Error("not base64: '" + std::string(1, c) + "' in \"" + text.substr(0, 40) +
                        "...\"");
        value = (value << 6) | static_cast<unsigned>(digit);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out += static_cast<char>((value >> bits) & 0xFF);
        }
    }
    return out;
}

Browser::Browser(const std::string& log_path, int width, int height) : log_path_(log_path) {
    const std::string path = chromium_path();
    if (path.empty())
        throw Error("no Chromium on PATH (install Debian's chromium, or set LAB_CHROMIUM)");
    profile_dir_ = log_path + ".profile";
    std::filesystem::remove_all(profile_dir_);
    std::filesystem::create_directories(profile_dir_);
    // A write to a browser that died must fail with EPIPE, not end the test.
    std::signal(SIGPIPE, SIG_IGN);

    int to[2], from[2];
    if (pipe2(to, O_CLOEXEC) != 0 || pipe2(from, O_CLOEXEC) != 0)
        throw Error(std::string("pipe: ") + std::strerror(errno));
    // Flags as for a machine whose network is closed: nothing in the
    // background, no first-run page, no GPU, one scale.
    std::vector<std::string> args = {
        path,
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-quic",
        "--no-first-run",
        "--no-default-browser-check",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--disable-dev-shm-usage",
        "--hide-scrollbars",
        "--force-device-scale-factor=1",
        "--window-size=" + std::to_string(width) + "," + std::to_string(height),
        "--user-data-dir=" + profile_dir_,
        "--remote-debugging-pipe",
        "about:blank"};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    pid_ = fork();
    if (pid_ < 0) throw Error(std::string("fork: ") + std::strerror(errno));
    if (pid_ == 0) {
        // The browser and its helpers in a group of their own, killed whole
        // by the destructor, and the browser gone with the test.
        setpgid(0, 0);
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        const int r = fcntl(to[0], F_DUPFD, 10), w = fcntl(from[1], F_DUPFD, 10);
        const int log = open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int null = open("/dev/null", O_RDONLY);
        if (r < 0 || w < 0 || log < 0 || null < 0 || dup2(r, 3) < 0 || dup2(w, 4) < 0 ||
            dup2(null, 0) < 0 || dup2(log, 1) < 0 || dup2(log, 2) < 0)
            _exit(126);
        execv(path.c_str(), argv.data());
        _exit(127);
    }
    close(to[0]);
    close(from[1]);
    to_browser_ = to[1];
    from_browser_ = from[0];

    // The page it opened: attach with a flat session, then the domains whose
    // events the tests read.
    const json targets = call("Target.getTargets", json::object(), false);
    for (const json& t : targets["targetInfos"])
        if (t.value("type", "") == "page") {
            session_ = call("Target.attachToTarget",
                            {{"targetId", t["targetId"]}, {"flatten", true}}, false)["sessionId"];
            break;
        }
    if (session_.empty()) fail("no page to attach to among " + targets.dump());
    for (const char* domain : {"Page.enable", "Runtime.enable", "Log.enable"}) call(domain);
}

Browser::~Browser() {
    if (pid_ > 0) {
        try {
            json close = {{"id", next_id_++}, {"method", "Browser.close"}};
            send(close);
        } catch (const Error&) {
        }
        int status = 0;
        const auto deadline = Clock::now() + std::chrono::seconds(5);
        while (waitpid(pid_, &status, WNOHANG) == 0 && Clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        kill(-pid_, SIGKILL);  // whatever of the group is left
        waitpid(pid_, &status, WNOHANG);
    }
    if (to_browser_ >= 0) close(to_browser_);
    if (from_browser_ >= 0) close(from_browser_);
    std::error_code ignored;
    std::filesystem::remove_all(profile_dir_, ignored);
}

void Browser::fail(const std::string& what) const {
    std::string log = read_text(log_path_);
    if (log.size() > 4000) log = "..." + log.substr(log.size() - 4000);
    throw Error("chromium: " + what + "\nits log (" + log_path_ + "):\n" + log);
}

void Browser::send(const json& message) {
    const std::string text = message.dump() + '\0';
    for (size_t done = 0; done < text.size();) {
        const ssize_t n = write(to_browser_, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) fail(std::string("writing to the browser: ") + std::strerror(errno));
        done += static_cast<size_t>(n);
    }
}

json Browser::next_message(Clock::time_point deadline, const std::string& waiting_for) {
    for (;;) {
        if (const size_t end = pending_.find('\0'); end != std::string::npos) {
            json message = json::parse(pending_.substr(0, end), nullptr, false);
            pending_.erase(0, end + 1);
            if (message.is_discarded()) fail("a message that is not JSON");
            return message;
        }
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0)
            fail("no " + waiting_for + " within " + std::to_string(kTimeout.count()) + " s");
        pollfd p{from_browser_, POLLIN, 0};
        const int ready = poll(&p, 1, static_cast<int>(left));
        if (ready < 0 && errno == EINTR) continue;
        if (ready < 0) fail(std::string("poll: ") + std::strerror(errno));
        if (ready == 0) continue;
        char buf[65536];
        const ssize_t n = read(from_browser_, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) fail("the browser closed its pipe (exited?) while waiting for " + waiting_for);
        pending_.append(buf, static_cast<size_t>(n));
    }
}

void Browser::note_event(const json& message) {
    const std::string method = message.value("method", "");
    const json& params = message.contains("params") ? message["params"] : json::object();
    if (method == "Runtime.exceptionThrown") {
        const json& d = params["exceptionDetails"];
        page_errors_.push_back("exception: " + (d.contains("exception")
                                                    ? d["exception"].value("description", "")
                                                    : d.value("text", "")));
    } else if (method == "Runtime.consoleAPICalled" && params.value("type", "") == "error") {
        std::string text = "console.error:";
        for (const json& a : params["args"])
            text += " " + (a.contains("value") ? a["value"].dump() : a.value("description", ""));
        page_errors_.push_back(text);
    } else if (method == "Log.entryAdded" && params["entry"].value("level", "") == "error") {
        page_errors_.push_back(params["entry"].value("text", "") + " " +
                               params["entry"].value("url", ""));
    }
    events_.push_back(message);
}

json Browser::call(const std::string& method, const json& params, bool to_page) {
    const int id = next_id_++;
    json message = {{"id", id}, {"method", method}, {"params", params}};
    if (to_page && !session_.empty()) message["sessionId"] = session_;
    send(message);
    const auto deadline = Clock::now() + kTimeout;
    for (;;) {
        json reply = next_message(deadline, "reply to " + method);
        if (!reply.contains("id")) {
            note_event(reply);
            continue;
        }
        if (reply["id"] != id) continue;
        if (reply.contains("error"))
            fail(method + " " + params.dump().substr(0, 200) + ": " + reply["error"].dump());
        return reply.value("result", json::object());
    }
}

void Browser::navigate(const std::string& url) {
    std::erase_if(events_,
                  [](const json& e) { return e.value("method", "") == "Page.loadEventFired"; });
    const json result = call("Page.navigate", {{"url", url}});
    if (result.contains("errorText")) fail("loading " + url + ": " + result["errorText"].dump());
    const auto deadline = Clock::now() + kTimeout;
    for (;;) {
        for (const json& e : events_)
            if (e.value("method", "") == "Page.loadEventFired") return;
        json message = next_message(deadline, "the load event of " + url);
        if (!message.contains("id")) note_event(message);
    }
}

json Browser::evaluate(const std::string& expression) {
    const json result =
        call("Runtime.evaluate",
             {{"expression", expression}, {"returnByValue", true}, {"awaitPromise", true}});
    if (result.contains("exceptionDetails")) {
        const json& d = result["exceptionDetails"];
        fail("evaluating " + expression.substr(0, 200) + ": " +
             (d.contains("exception") ? d["exception"].value("description", "")
                                      : d.value("text", "")));
    }
    return result["result"].value("value", json());
}

Image Browser::screenshot(const std::string& png_path) {
    const json metrics = call("Page.getLayoutMetrics");
    const json& size = metrics["cssContentSize"];
    const json clip = {
        {"x", 0}, {"y", 0}, {"width", size["width"]}, {"height", size["height"]}, {"scale", 1}};
    const json shot = call("Page.captureScreenshot",
                           {{"format", "png"}, {"captureBeyondViewport", true}, {"clip", clip}});
    const std::string bytes = base64_decode(shot["data"].get<std::string>());
    if (!png_path.empty()) {
        std::filesystem::create_directories(std::filesystem::path(png_path).parent_path());
        write_text(png_path, bytes);
    }
    return decode_png(bytes, "the screenshot of the page");
}

json check_accessibility(Browser& browser) {
    const json found = browser.evaluate(kAccessibilityJs);
    MESSAGE(found["texts"] << " text nodes looked at, " << found["violations"].size()
                           << " violations");
    std::map<std::string, int> per_rule;
    for (const json& v : found["violations"])
        if (++per_rule[v[0]] <= 5)
            FAIL_CHECK(v[0].get<std::string>()
                       << " " << v[1].get<std::string>() << ": " << v[2].get<std::string>());
    for (const auto& [rule, count] : per_rule) MESSAGE(rule << ": " << count << " elements");
    CHECK(found["violations"].empty());
    return found;
}

std::optional<CommandResult> parse_html_strictly(const std::string& path) {
    const CommandResult probe = run_command("/usr/bin/python3 -c 'import html5lib'");
    if (probe.exit_code != 0) {
        const char* require = std::getenv("LAB_REQUIRE_BROWSER");
        const std::string why = "no python3-html5lib: scripts/test.sh installs it";
        if (require && std::string(require) == "1")
            FAIL(why << "; LAB_REQUIRE_BROWSER=1 asks for it");
        MESSAGE("SKIP this case: " << why);
        return std::nullopt;
    }
    return run_command(
        "/usr/bin/python3 -c 'import sys, html5lib; "
        "html5lib.HTMLParser(strict=True).parse(open(sys.argv[1], \"rb\")); print(\"ok\")' " +
        shell_quote(path));
}

}  // namespace fw::test
