#include "grading/class/taken.hpp"

#include <nlohmann/json.hpp>

#include "grading/release/release.hpp"
#include "grading/report/report_text.hpp"

namespace grading::cls {

namespace fs = std::filesystem;
using nlohmann::json;

std::optional<Taken> read_taken(const fs::path& file) {
    try {
        const json j = json::parse(read_file(file));
        Taken t;
        t.key = j.at("key");
        t.graded = j.at("graded");
        t.missing = j.at("missing").get<std::vector<std::string>>();
        t.extra = j.at("extra").get<std::vector<std::string>>();
        t.hashes = j.at("hashes").get<std::map<std::string, std::string>>();
        t.files_txt = j.at("files_txt");
        return t;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

void write_taken(const fs::path& file, const Taken& t) {
    std::error_code ec;
    try {
        const json j = {{"key", t.key},     {"graded", t.graded}, {"missing", t.missing},
                        {"extra", t.extra}, {"hashes", t.hashes}, {"files_txt", t.files_txt}};
        const std::string text = j.dump(1) + "\n";  // throws on a name that is not UTF-8
        fs::create_directories(file.parent_path());
        const fs::path partial = file.string() + ".part";
        report::write_text_file(partial.string(), text);
        fs::rename(partial, file);
    } catch (const std::exception&) {
        fs::remove(file, ec);  // not kept: the next run unpacks it again
    }
}

}  // namespace grading::cls
