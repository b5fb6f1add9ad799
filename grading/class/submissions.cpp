#include "grading/class/submissions.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>

#include "framework/error.hpp"
#include "grading/class/content_hash.hpp"
#include "grading/class/unpack.hpp"

namespace grading::cls {

namespace fs = std::filesystem;

namespace {

const char* const kMetadata = "submission_metadata.yml";

bool ends_with(const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The key of an archive: its name without the extension; none when it is
// no archive this reads.
std::optional<std::string> archive_key(const std::string& name) {
    for (const char* ext : {".tar.gz", ".tgz", ".zip", ".tar"})
        if (ends_with(name, ext) && name.size() > std::string(ext).size())
            return name.substr(0, name.size() - std::string(ext).size());
    return std::nullopt;
}

std::string scalar(const YAML::Node& map, const char* key) {
    const YAML::Node v = map[key];
    return v && v.IsScalar() ? v.as<std::string>() : std::string();
}

// Gradescope's export: {submission_N: {":submitters": [{":name", ":sid",
// ":email"}], ":created_at": TIME, ...}, ...}, beside the folders it names.
std::vector<Submission> gradescope_export(const fs::path& dir, std::vector<std::string>& skipped) {
    const fs::path file = dir / kMetadata;
    YAML::Node doc;
    try {
        doc = YAML::LoadFile(file.string());
    } catch (const YAML::Exception& e) {
        throw fw::UsageError(file.string() + ": " + e.what() +
                             " (Gradescope's export writes it; grade-class reads its "
                             "submitters)");
    }
    if (!doc.IsMap())
        throw fw::UsageError(file.string() +
                             ": expected a map of submission folders to their metadata");
    std::vector<Submission> found;
    for (const auto& entry : doc) {
        const std::string folder = entry.first.as<std::string>();
        const YAML::Node meta = entry.second;
        Submission s;
        s.key = folder;
        s.path = dir / folder;
        if (folder.find('/') != std::string::npos || folder == ".." || folder == "." ||
            !fs::is_directory(fs::symlink_status(s.path))) {
            skipped.push_back(folder + " (named in " + kMetadata + ", but no folder)");
            continue;
        }
        if (meta.IsMap() && meta[":submitters"] && meta[":submitters"].IsSequence())
            for (const YAML::Node& who : meta[":submitters"])
                if (who.IsMap())
                    s.students.push_back(
                        {scalar(who, ":name"), scalar(who, ":email"), scalar(who, ":sid")});
        if (meta.IsMap()) {
            const std::string created = scalar(meta, ":created_at");
            if (!created.empty()) {
                try {
                    s.submitted = parse_time(created);
                } catch (const fw::Error&) {
                    skipped.push_back(folder + " (its :created_at '" + created +
                                      "' is no time; graded, late unknown)");
                }
            }
        }
        found.push_back(std::move(s));
    }
    return found;
}

}  // namespace

std::vector<Submission> find_submissions(const fs::path& dir, std::vector<std::string>& skipped) {
    if (!fs::is_directory(dir))
        throw fw::UsageError("'" + dir.string() + "' is not a folder of submissions");
    std::vector<Submission> found;
    if (fs::exists(dir / kMetadata)) {
        found = gradescope_export(dir, skipped);
    } else {
        for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
            const std::string name = e.path().filename().string();
            if (name.empty() || name[0] == '.') continue;
            const fs::file_status st = fs::symlink_status(e.path());
            Submission s;
            s.path = e.path();
            if (fs::is_directory(st)) {
                s.key = name;
                s.kind =
                    fs::exists(e.path() / ".git") ? SubmissionKind::Git : SubmissionKind::Folder;
            } else if (const auto key = archive_key(name); key && fs::is_regular_file(st)) {
                s.key = *key;
                s.kind = SubmissionKind::Archive;
            } else {
                skipped.push_back(name + " (neither a folder nor a .zip, .tar.gz or .tar)");
                continue;
            }
            found.push_back(std::move(s));
        }
    }
    std::sort(found.begin(), found.end(),
              [](const Submission& a, const Submission& b) { return a.key < b.key; });
    for (size_t i = 1; i < found.size(); ++i)
        if (found[i].key == found[i - 1].key)
            throw fw::UsageError("two submissions in '" + dir.string() + "' are both named '" +
                                 found[i].key + "' (" + found[i - 1].path.filename().string() +
                                 ", " + found[i].path.filename().string() +
                                 "): rename one, reports are kept by name");
    return found;
}

Unpacked unpack(const Submission& s, const fs::path& dest, std::optional<std::time_t> deadline,
                const UnpackLimits& limits) {
    std::error_code ec;
    fs::remove_all(dest, ec);
    fs::create_directories(dest);
    Unpacked u;
    switch (s.kind) {
        case SubmissionKind::Folder:
            u = copy_folder(s.path, dest, limits);
            break;
        case SubmissionKind::Archive:
            u = extract_archive(s.path, dest, limits);
            break;
        case SubmissionKind::Git:
            u = checkout_before(s.path, dest, deadline, limits);
            break;
    }
    if (u.ok && s.kind != SubmissionKind::Git && deadline && s.submitted)
        u.late_commits = *s.submitted > *deadline ? 1 : 0;
    return u;
}

std::string source_key(const Submission& s, std::optional<std::time_t> deadline, Unpacked& u,
                       const UnpackLimits& limits) {
    u = Unpacked{};
    std::optional<std::string> key;
    std::error_code ec;
    switch (s.kind) {
        case SubmissionKind::Folder:
            key = folder_key(s.path, limits);
            break;
        case SubmissionKind::Archive:
            if (const auto size = fs::file_size(s.path, ec); !ec && size <= limits.bytes) {
                std::ifstream in(s.path, std::ios::binary);
                const std::string bytes((std::istreambuf_iterator<char>(in)),
                                        std::istreambuf_iterator<char>());
                if (in.eof() && bytes.size() == size) key = "archive\n" + content_hash(bytes);
            }
            break;
        case SubmissionKind::Git:
            u = commit_before(s.path, deadline);
            if (u.ok) key = "git\n" + u.commit;
            break;
    }
    if (!key) return "";
    u.ok = true;
    if (s.kind != SubmissionKind::Git && deadline && s.submitted)
        u.late_commits = *s.submitted > *deadline ? 1 : 0;
    return *key + "\n" + std::to_string(limits.bytes) + " " + std::to_string(limits.files);
}

std::time_t parse_time(const std::string& text) {
    int y = 0, mo = 0, d = 0, h = 0, mi = 0, sec = 0, used = 0;
    const int n =
        std::sscanf(text.c_str(), "%4d-%2d-%2d%*1[T ]%2d:%2d%n", &y, &mo, &d, &h, &mi, &used);
    if (n < 5)
        throw fw::UsageError("'" + text +
                             "' is not a time: expected YYYY-MM-DDTHH:MM[:SS][Z|+HH:MM], UTC "
                             "unless a zone is given");
    std::string rest = text.substr(static_cast<size_t>(used));
    if (!rest.empty() && rest[0] == ':') {
        int more = 0;
        if (std::sscanf(rest.c_str(), ":%2d%n", &sec, &more) != 1)
            throw fw::UsageError("'" + text + "' has no seconds after its last ':'");
        rest = rest.substr(static_cast<size_t>(more));
        if (!rest.empty() && rest[0] == '.') {  // a fraction of a second
            const size_t digits = rest.find_first_not_of("0123456789", 1);
            rest.erase(0, digits == std::string::npos ? rest.size() : digits);
        }
    }
    while (!rest.empty() && rest[0] == ' ') rest.erase(0, 1);
    long offset = 0;
    if (!rest.empty() && rest != "Z" && rest != "UTC") {
        int oh = 0, om = 0;
        char sign = 0;
        if (std::sscanf(rest.c_str(), "%c%2d:%2d", &sign, &oh, &om) != 3 ||
            (sign != '+' && sign != '-'))
            throw fw::UsageError("'" + text + "' has a zone '" + rest +
                                 "' that is neither Z nor +HH:MM");
        offset = (sign == '-' ? -1 : 1) * (oh * 3600L + om * 60L);
    }
    std::tm tm{};
    tm.tm_year = y - 1900;
    tm.tm_mon = mo - 1;
    tm.tm_mday = d;
    tm.tm_hour = h;
    tm.tm_min = mi;
    tm.tm_sec = sec;
    if (mo < 1 || mo > 12 || d < 1 || d > 31 || h > 23 || mi > 59 || sec > 60)
        throw fw::UsageError("'" + text + "' is not a valid date and time");
    return timegm(&tm) - offset;
}

}  // namespace grading::cls
