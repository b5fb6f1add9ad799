#include "grading/run/repository.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "framework/error.hpp"

namespace grading {

namespace fs = std::filesystem;

std::string source_root() {
    const char* root = std::getenv("LAB_ROOT");
    return root && *root ? root : LAB_SOURCE_DIR;
}

std::string sources_root(const std::string& root) {
    const char* sources = std::getenv("LAB_SOURCES");
    return sources && *sources ? sources : root;
}

std::string resolve_lab_binary(const std::string& given) {
    std::string path = given;
    if (path.empty()) {
        std::error_code ec;
        const fs::path self = fs::read_symlink("/proc/self/exe", ec);
        if (ec)
            throw fw::UsageError(
                "cannot find course's own directory (/proc/self/exe): pass --lab PATH");
        path = (self.parent_path() / "lab").string();
    }
    const std::string abs = fs::absolute(path).string();
    if (!fs::exists(abs))
        throw fw::UsageError("no lab executable at '" + abs +
                             "'; build it (cmake --build build --target lab) or pass --lab PATH");
    if (!fs::is_regular_file(abs) || access(abs.c_str(), X_OK) != 0)
        throw fw::UsageError("'" + abs +
                             "' is not an executable file; pass --lab with the `lab` executable");
    return abs;
}

}  // namespace grading
