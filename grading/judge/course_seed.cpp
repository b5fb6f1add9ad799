#include "grading/judge/course_seed.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>

#include "framework/error.hpp"

namespace grading {

namespace fs = std::filesystem;

CourseSeed course_seed(const std::string& root) {
    if (const char* text = std::getenv("COURSE_SEED"); text && *text) {
        char* end = nullptr;
        const unsigned long v = std::strtoul(text, &end, 10);
        if (*text == '-' || *end != '\0' || v > 0xffffffffUL)
            throw fw::UsageError("COURSE_SEED='" + std::string(text) +
                                 "' is not a number from 0 to 4294967295");
        return {static_cast<unsigned>(v), "COURSE_SEED"};
    }
    const fs::path path = fs::path(root) / kCourseSeedFile;
    std::error_code ec;
    if (!fs::exists(path, ec))
        return {0, "none set (course bless makes " + std::string(kCourseSeedFile) + ")"};
    std::ifstream in(path);
    const nlohmann::json doc = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (!doc.is_object() || !doc.contains("seed") || !doc["seed"].is_number_unsigned() ||
        doc["seed"].get<std::uint64_t>() > 0xffffffffULL)
        throw fw::UsageError(std::string(kCourseSeedFile) +
                             ": expected {\"seed\": N} with N from 0 to 4294967295");
    return {doc["seed"].get<unsigned>(), kCourseSeedFile};
}

bool make_course_seed(const std::string& root, unsigned& made) {
    const fs::path path = fs::path(root) / kCourseSeedFile;
    std::error_code ec;
    if (fs::exists(path, ec)) return false;
    made = std::random_device{}();
    std::ofstream out(path);
    out << nlohmann::json{{"seed", made}}.dump() << "\n";
    if (!out.flush()) throw fw::Error("cannot write '" + path.string() + "'");
    return true;
}

}  // namespace grading
