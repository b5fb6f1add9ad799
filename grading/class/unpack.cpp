#include "grading/class/unpack.hpp"

#include <archive.h>
#include <archive_entry.h>
#include <git2.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <memory>
#include <mutex>

#include "grading/class/content_hash.hpp"

namespace grading::cls {

namespace fs = std::filesystem;

namespace {

Unpacked refused(const std::string& why) {
    Unpacked u;
    u.error = why;
    return u;
}

// Whether `rel` is a relative path with no `..` and no empty part.
bool safe_relative(const std::string& rel) {
    if (rel.empty() || rel[0] == '/') return false;
    const fs::path p(rel);
    for (const fs::path& part : p)
        if (part == ".." || part.string().find('\0') != std::string::npos) return false;
    return true;
}

bool write_file(const fs::path& to, const char* data, size_t size) {
    std::error_code ec;
    fs::create_directories(to.parent_path(), ec);
    std::ofstream out(to, std::ios::binary | std::ios::trunc);
    out.write(data, static_cast<std::streamsize>(size));
    return static_cast<bool>(out);
}

// Counts what is unpacked against the limits.
struct Budget {
    const UnpackLimits& limits;
    std::uint64_t bytes = 0, files = 0;
    std::string over(std::uint64_t more) {
        bytes += more;
        ++files;
        if (bytes > limits.bytes)
            return "it unpacks to more than " + std::to_string(limits.bytes >> 20) + " MiB";
        if (files > limits.files)
            return "it holds more than " + std::to_string(limits.files) + " files";
        return "";
    }
};

}  // namespace

Unpacked copy_folder(const fs::path& from, const fs::path& dest, const UnpackLimits& limits) {
    Budget budget{limits};
    std::error_code ec;
    fs::recursive_directory_iterator it(from, fs::directory_options::none, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
        const fs::file_status st = fs::symlink_status(it->path());
        if (it->path().filename() == ".git" && fs::is_directory(st)) {
            it.disable_recursion_pending();
            continue;
        }
        if (!fs::is_regular_file(st)) continue;
        const std::string why = budget.over(fs::file_size(it->path(), ec));
        if (!why.empty()) return refused("the folder was not graded: " + why);
        const fs::path to = dest / it->path().lexically_relative(from);
        fs::create_directories(to.parent_path(), ec);
        fs::copy_file(it->path(), to, fs::copy_options::overwrite_existing, ec);
        if (ec) return refused("cannot copy " + it->path().string() + ": " + ec.message());
    }
    if (ec) return refused("cannot read the folder " + from.string() + ": " + ec.message());
    Unpacked u;
    u.ok = true;
    return u;
}

std::optional<std::string> folder_key(const fs::path& from, const UnpackLimits& limits) {
    Budget budget{limits};
    std::vector<std::string> lines;
    std::error_code ec;
    fs::recursive_directory_iterator it(from, fs::directory_options::none, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
        const fs::file_status st = fs::symlink_status(it->path());
        if (it->path().filename() == ".git" && fs::is_directory(st)) {
            it.disable_recursion_pending();
            continue;
        }
        if (!fs::is_regular_file(st)) continue;
        if (!budget.over(fs::file_size(it->path(), ec)).empty() || ec) return std::nullopt;
        std::ifstream in(it->path(), std::ios::binary);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (!in.good() && !in.eof()) return std::nullopt;
        lines.push_back(it->path().lexically_relative(from).string() + '\0' + content_hash(text));
    }
    if (ec) return std::nullopt;
    std::sort(lines.begin(), lines.end());
    std::string all = "folder\n";
    for (const std::string& line : lines) all += line + '\n';
    return content_hash(all);
}

Unpacked extract_archive(const fs::path& archive, const fs::path& dest,
                         const UnpackLimits& limits) {
    std::unique_ptr<struct archive, int (*)(struct archive*)> a(archive_read_new(),
                                                                archive_read_free);
    archive_read_support_filter_gzip(a.get());
    archive_read_support_format_zip(a.get());
    archive_read_support_format_tar(a.get());
    const std::string name = archive.filename().string();
    if (archive_read_open_filename(a.get(), archive.c_str(), 1 << 16) != ARCHIVE_OK)
        return refused("the archive " + name + " cannot be read: " + archive_error_string(a.get()));
    Budget budget{limits};
    std::string data;
    for (;;) {
        struct archive_entry* entry = nullptr;
        const int r = archive_read_next_header(a.get(), &entry);
        if (r == ARCHIVE_EOF) break;
        if (r != ARCHIVE_OK && r != ARCHIVE_WARN)
            return refused("the archive " + name + " is broken: " + archive_error_string(a.get()));
        const char* path = archive_entry_pathname(entry);
        const std::string rel = path ? path : "";
        if (archive_entry_filetype(entry) != AE_IFREG) continue;
        if (!safe_relative(rel))
            return refused("the archive " + name + " holds '" + rel +
                           "', a path outside its own folder: nothing of it was graded");
        if (archive_entry_size_is_set(entry)) {
            const std::string why =
                budget.over(static_cast<std::uint64_t>(archive_entry_size(entry)));
            if (!why.empty()) return refused("the archive " + name + " was not graded: " + why);
        }
        data.clear();
        const void* block = nullptr;
        size_t size = 0;
        la_int64_t offset = 0;
        int read = 0;
        while ((read = archive_read_data_block(a.get(), &block, &size, &offset)) == ARCHIVE_OK) {
            if (static_cast<std::uint64_t>(offset) + size > limits.bytes)
                return refused("the archive " + name + " was not graded: '" + rel +
                               "' unpacks to more than its size says");
            if (data.size() < static_cast<size_t>(offset)) data.resize(static_cast<size_t>(offset));
            data.append(static_cast<const char*>(block), size);
        }
        if (read != ARCHIVE_EOF)
            return refused("the archive " + name + " is broken at '" + rel +
                           "': " + archive_error_string(a.get()));
        if (!write_file(dest / rel, data.data(), data.size()))
            return refused("cannot write " + (dest / rel).string());
    }
    Unpacked u;
    u.ok = true;
    return u;
}

namespace {

template <class T, void (*Free)(T*)>
struct Owned {
    T* p = nullptr;
    ~Owned() {
        if (p) Free(p);
    }
};

std::string git_message(const std::string& what) {
    const git_error* e = git_error_last();
    return what + ": " + (e && e->message ? e->message : "libgit2 gave no reason");
}

struct TreeWriter {
    git_repository* repo;
    fs::path dest;
    Budget budget;
    std::string error;
};

int write_entry(const char* root, const git_tree_entry* entry, void* payload) {
    auto* w = static_cast<TreeWriter*>(payload);
    const git_filemode_t mode = git_tree_entry_filemode(entry);
    if (mode != GIT_FILEMODE_BLOB && mode != GIT_FILEMODE_BLOB_EXECUTABLE) return 0;
    const std::string rel = std::string(root) + git_tree_entry_name(entry);
    if (!safe_relative(rel)) {
        w->error = "the repository holds '" + rel + "', a path outside its own folder";
        return -1;
    }
    Owned<git_blob, git_blob_free> blob;
    if (git_blob_lookup(&blob.p, w->repo, git_tree_entry_id(entry)) != 0) {
        w->error = git_message("cannot read '" + rel + "'");
        return -1;
    }
    const auto size = static_cast<std::uint64_t>(git_blob_rawsize(blob.p));
    const std::string why = w->budget.over(size);
    if (!why.empty()) {
        w->error = "the repository was not graded: " + why;
        return -1;
    }
    if (!write_file(w->dest / rel, static_cast<const char*>(git_blob_rawcontent(blob.p)),
                    static_cast<size_t>(size))) {
        w->error = "cannot write " + (w->dest / rel).string();
        return -1;
    }
    return 0;
}

}  // namespace

namespace {

// The newest commit of HEAD's history at or before `deadline`, into
// `chosen`; `u` counts the newer ones, or says why there is none.
bool choose_commit(git_repository* repo, const std::string& name,
                   std::optional<std::time_t> deadline, Owned<git_commit, git_commit_free>& chosen,
                   Unpacked& u) {
    Owned<git_revwalk, git_revwalk_free> walk;
    if (git_revwalk_new(&walk.p, repo) != 0 || git_revwalk_push_head(walk.p) != 0) {
        u = refused(git_message("the repository " + name + " has no commit on HEAD"));
        return false;
    }
    git_revwalk_sorting(walk.p, GIT_SORT_TIME);
    git_oid oid;
    while (git_revwalk_next(&oid, walk.p) == 0) {
        Owned<git_commit, git_commit_free> commit;
        if (git_commit_lookup(&commit.p, repo, &oid) != 0) {
            u = refused(git_message("cannot read a commit"));
            return false;
        }
        if (deadline && git_commit_time(commit.p) > *deadline) {
            ++u.late_commits;
            continue;
        }
        std::swap(chosen.p, commit.p);
        break;
    }
    if (!chosen.p) u = refused("the repository " + name + " has no commit before the deadline");
    return chosen.p != nullptr;
}

std::string commit_id(const git_commit* commit) {
    char id[GIT_OID_HEXSZ + 1] = {};
    git_oid_tostr(id, sizeof id, git_commit_id(commit));
    return id;
}

// The repository opened (libgit2 set up once for the process) and its
// commit chosen for the deadline; false with `u` saying why where either fails.
bool open_chosen(const fs::path& repository, std::optional<std::time_t> deadline,
                 Owned<git_repository, git_repository_free>& repo,
                 Owned<git_commit, git_commit_free>& chosen, Unpacked& u) {
    static std::once_flag once;
    std::call_once(once, [] { git_libgit2_init(); });
    const std::string name = repository.filename().string();
    if (git_repository_open(&repo.p, repository.c_str()) != 0) {
        u = refused(git_message("the repository " + name + " cannot be opened"));
        return false;
    }
    if (!choose_commit(repo.p, name, deadline, chosen, u)) return false;
    u.commit = commit_id(chosen.p);
    return true;
}

}  // namespace

Unpacked commit_before(const fs::path& repository, std::optional<std::time_t> deadline) {
    Owned<git_repository, git_repository_free> repo;
    Owned<git_commit, git_commit_free> chosen;
    Unpacked u;
    if (!open_chosen(repository, deadline, repo, chosen, u)) return u;
    u.ok = true;
    return u;
}

Unpacked checkout_before(const fs::path& repository, const fs::path& dest,
                         std::optional<std::time_t> deadline, const UnpackLimits& limits) {
    Owned<git_repository, git_repository_free> repo;
    Owned<git_commit, git_commit_free> chosen;
    Unpacked u;
    if (!open_chosen(repository, deadline, repo, chosen, u)) return u;
    Owned<git_tree, git_tree_free> tree;
    if (git_commit_tree(&tree.p, chosen.p) != 0)
        return refused(git_message("cannot read the tree of commit " + u.commit));
    TreeWriter writer{repo.p, dest, Budget{limits}, ""};
    if (git_tree_walk(tree.p, GIT_TREEWALK_PRE, write_entry, &writer) != 0)
        return refused(writer.error.empty() ? git_message("cannot read the tree of " + u.commit)
                                            : writer.error);
    u.ok = true;
    return u;
}

}  // namespace grading::cls
