// A lab's units.json parsed as soon as the child has sent it, while the
// child goes on to draw the lab's frames: the child calls the unit
// functions before it renders, and parsing thousands of results is most of
// judging them. judge_lab takes the parse of exactly the bytes it reads,
// and parses them itself where none was started, so the verdicts never
// depend on whether the early parse ran.
//
// What a child sends is not trusted: a record over kUnitsJsonMax is left
// alone (judge_lab refuses it too), at most kKept parses are held at a
// time (a record of a path already held replaces its parse), and at most
// kStartsPerLab parses a lab are ever started, however many records a child
// sends; past these, judge_lab parses what it reads, as it would anyway.
#pragma once

#include <cstddef>
#include <future>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace grading {

// The largest units.json course reads.
constexpr size_t kUnitsJsonMax = 16 * 1024 * 1024;

class EarlyUnits {
public:
    static constexpr size_t kKept = 2;
    static constexpr size_t kStartsPerLab = 2;

    // For the records of a child (or children) grading `labs` labs.
    explicit EarlyUnits(size_t labs) : starts_left_(kStartsPerLab * labs) {}
    EarlyUnits(const EarlyUnits&) = delete;
    EarlyUnits& operator=(const EarlyUnits&) = delete;
    ~EarlyUnits();
    // For StreamedOutputs (grading/run/child.hpp: RecordDone): a record named
    // units.json starts its parse on a thread of its own.
    void record_done(const std::string& path, const std::string& bytes);
    // The parse of `bytes` (json::parse without exceptions, as judge_lab
    // makes it), waited for and removed; nothing when none was started for
    // these very bytes.
    std::optional<nlohmann::json> take(std::string_view bytes);

private:
    struct Parse {
        std::string path;
        std::shared_ptr<const std::string> bytes;
        std::future<nlohmann::json> json;
    };
    std::mutex mutex_;
    std::vector<Parse> parses_;
    size_t starts_left_;
};

}  // namespace grading
