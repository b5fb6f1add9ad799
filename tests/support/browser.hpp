// Headless Chromium for tests that look at what a person would see: a page
// loaded, its layout measured, its pixels captured. Driven through the
// DevTools protocol over a pipe (--remote-debugging-pipe: the browser reads
// commands on its fd 3 and writes replies and events on its fd 4, each a JSON
// text ended by '\0'), so no port is opened and nothing else is needed.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "framework/image.hpp"
#include "tests/support/test_support.hpp"

namespace fw::test {

// The browser to run: $LAB_CHROMIUM, else chromium (Debian's package,
// installed by scripts/test.sh), chromium-browser or google-chrome on PATH;
// "" when there is none.
std::string chromium_path();

// For a test that needs a browser where there is none: exits 77 (ctest's
// SKIP) with the reason, or fails when LAB_REQUIRE_BROWSER=1 (CI sets it).
// Returns the browser's path otherwise.
std::string chromium_or_skip();

// For one case that needs a browser in a test whose other cases do not:
// true where there is one; else false after saying why (the case is then
// skipped), or a failure when LAB_REQUIRE_BROWSER=1.
bool chromium_for_case();

// Standard base64 (RFC 4648), decoded independently of the reports' encoder;
// throws on a character outside its alphabet.
std::string base64_decode(const std::string& text);

class Browser {
public:
    // Starts the browser with a window of width x height CSS pixels (device
    // scale 1) and attaches to its page. Throws fw::Error naming the browser
    // and what it printed when it cannot start. Its log goes to `log_path`.
    Browser(const std::string& log_path, int width = 1280, int height = 900);
    ~Browser();
    Browser(const Browser&) = delete;
    Browser& operator=(const Browser&) = delete;

    // A command to the page (or, with to_page false, to the browser); its
    // result. Throws with the method and the protocol's message on an error,
    // and when no reply comes within the timeout.
    nlohmann::json call(const std::string& method,
                        const nlohmann::json& params = nlohmann::json::object(),
                        bool to_page = true);
    // Loads `url` and waits for its load event.
    void navigate(const std::string& url);
    // The value of a JavaScript expression in the page (promises awaited).
    // Throws with the exception's text when it throws.
    nlohmann::json evaluate(const std::string& expression);
    // The whole page (beyond the window), as pixels; written to `png_path`
    // too when it is not empty.
    Image screenshot(const std::string& png_path = "");
    // What the page reported as errors: uncaught exceptions, console.error,
    // and resources that failed to load.
    const std::vector<std::string>& page_errors() const { return page_errors_; }

private:
    nlohmann::json next_message(std::chrono::steady_clock::time_point deadline,
                                const std::string& waiting_for);
    void send(const nlohmann::json& message);
    void note_event(const nlohmann::json& message);
    [[noreturn]] void fail(const std::string& what) const;

    pid_t pid_ = -1;
    int to_browser_ = -1;
    int from_browser_ = -1;
    int next_id_ = 1;
    std::string log_path_;
    std::string profile_dir_;
    std::string session_;
    std::string pending_;                 // bytes read past the last '\0'
    std::vector<nlohmann::json> events_;  // events not yet waited for
    std::vector<std::string> page_errors_;
};

// The page's accessibility, checked by script as axe-core checks it at WCAG
// 2 AA for the rules a course's page could break (browser.cpp lists them):
// a failed check per violation (five a rule), and the whole finding,
// {"texts": text nodes looked at, "violations": [[rule, target, what]...]}.
nlohmann::json check_accessibility(Browser& browser);

// The HTML file at `path` parsed by html5lib (python3-html5lib, WHATWG's
// parsing algorithm) in strict mode, which refuses any parse error: its exit
// status and output, "ok\n" when it parsed. nullopt, after saying why, where
// html5lib is missing (a failure when LAB_REQUIRE_BROWSER=1).
std::optional<CommandResult> parse_html_strictly(const std::string& path);

}  // namespace fw::test
