// units.json parsed while the child renders (early_units.hpp).
#include "grading/judge/early_units.hpp"

#include <system_error>

namespace grading {

EarlyUnits::~EarlyUnits() {
    // The threads end before what they parse is gone.
    for (Parse& p : parses_)
        if (p.json.valid()) p.json.wait();
}

void EarlyUnits::record_done(const std::string& path, const std::string& bytes) {
    constexpr const char* kName = "/units.json";
    constexpr size_t kNameSize = 11;
    if (path.size() < kNameSize || path.compare(path.size() - kNameSize, kNameSize, kName) != 0)
        return;
    auto copy = std::make_shared<const std::string>(bytes);
    std::future<nlohmann::json> parsed;
    try {
        parsed = std::async(std::launch::async, [copy] {
            return nlohmann::json::parse(*copy, nullptr, /*allow_exceptions=*/false);
        });
    } catch (const std::system_error&) {
        return;  // no thread to be had: judge_lab parses it, later
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    parses_.push_back({std::move(copy), std::move(parsed)});
}

std::optional<nlohmann::json> EarlyUnits::take(const std::string& bytes) {
    std::future<nlohmann::json> found;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        for (auto it = parses_.begin(); it != parses_.end(); ++it) {
            if (*it->bytes != bytes) continue;
            found = std::move(it->json);
            parses_.erase(it);
            break;
        }
    }
    if (!found.valid()) return std::nullopt;
    return found.get();
}

}  // namespace grading
