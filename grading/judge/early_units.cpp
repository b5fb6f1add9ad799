// units.json parsed while the child renders (early_units.hpp).
#include "grading/judge/early_units.hpp"

#include <algorithm>
#include <system_error>

namespace grading {

EarlyUnits::~EarlyUnits() {
    // The threads end before what they parse is gone.
    for (Parse& p : parses_)
        if (p.json.valid()) p.json.wait();
}

void EarlyUnits::record_done(const std::string& path, const std::string& bytes) {
    static const std::string kName = "/units.json";
    if (path.size() < kName.size() ||
        path.compare(path.size() - kName.size(), kName.size(), kName) != 0 ||
        bytes.size() > kUnitsJsonMax)
        return;
    std::future<nlohmann::json> replaced;  // waited for outside the lock
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        const auto same = std::find_if(parses_.begin(), parses_.end(),
                                       [&](const Parse& p) { return p.path == path; });
        if (starts_left_ == 0 || (same == parses_.end() && parses_.size() >= kKept)) return;
        auto copy = std::make_shared<const std::string>(bytes);
        std::future<nlohmann::json> parsed;
        try {
            parsed = std::async(std::launch::async, [copy] {
                return nlohmann::json::parse(*copy, nullptr, /*allow_exceptions=*/false);
            });
        } catch (const std::system_error&) {
            return;  // no thread to be had: judge_lab parses it, later
        }
        --starts_left_;
        if (same != parses_.end()) {
            replaced = std::move(same->json);
            *same = {path, std::move(copy), std::move(parsed)};
        } else {
            parses_.push_back({path, std::move(copy), std::move(parsed)});
        }
    }
}

std::optional<nlohmann::json> EarlyUnits::take(std::string_view bytes) {
    std::future<nlohmann::json> found;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        const auto it = std::find_if(parses_.begin(), parses_.end(),
                                     [&](const Parse& p) { return *p.bytes == bytes; });
        if (it != parses_.end()) {
            found = std::move(it->json);
            parses_.erase(it);
        }
    }
    if (!found.valid()) return std::nullopt;
    return found.get();
}

}  // namespace grading
