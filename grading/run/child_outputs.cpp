// Reading back what a `lab` grade-child left in its work directory
// (child.hpp: ChildOutputs, run_lab_child), with limits: links, special files
// and anything over its size limit are refused.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "framework/error.hpp"
#include "grading/run/child.hpp"

namespace grading {

ChildOutputs::ChildOutputs(std::string dir, const ChildRun& run, const ChildLimits& limits)
    : dir_(std::move(dir)), run_(run) {
    const std::uint64_t total = directory_bytes(dir_);
    if (total > limits.work_dir_cap)
        too_large_ = "output too large: the child left " + std::to_string(total) +
                     " bytes in its work directory, more than the " +
                     mib_text(limits.work_dir_cap) + " limit";
}

std::string ChildOutputs::missing_reason(const std::string& name) const {
    if (!run_.ok()) return "the child " + run_.status.text() + " before writing " + name;
    const std::string error_file = name.substr(0, name.find('.')) + ".error.txt";
    std::string text, why;
    if (error_file != name && read(error_file, 64 * 1024, text, why)) {
        while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
        return "the lab could not produce " + name + ": " + text;
    }
    return "the child exited normally without writing " + name;
}

bool ChildOutputs::read(const std::string& name, std::uint64_t limit, std::string& bytes,
                        std::string& why) const {
    if (!too_large_.empty()) {
        why = too_large_;
        return false;
    }
    const std::string file = dir_ + "/" + name;
    struct stat st;
    if (lstat(file.c_str(), &st) != 0) {
        why = errno == ENOENT ? missing_reason(name) : name + ": " + std::strerror(errno);
        return false;
    }
    // A link could point at a reference image or any file course may read.
    if (!S_ISREG(st.st_mode) || st.st_nlink != 1) {
        why = name + " is not a regular file with one link; refused";
        return false;
    }
    if (static_cast<std::uint64_t>(st.st_size) > limit) {
        why = "output too large: " + name + " is " + std::to_string(st.st_size) +
              " bytes, more than the limit of " + std::to_string(limit);
        return false;
    }
    int fd = open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        why = "cannot read " + name + ": " + std::strerror(errno);
        return false;
    }
    bytes.clear();
    // The size lstat saw (within the limit), and one byte to see it grow.
    bytes.reserve(static_cast<size_t>(st.st_size) + 1);
    char buf[65536];
    ssize_t n;
    while ((n = ::read(fd, buf, sizeof buf)) > 0 && bytes.size() <= limit)
        bytes.append(buf, static_cast<size_t>(n));
    close(fd);
    if (bytes.size() > limit) {
        why = "output too large: " + name + " grew past " + std::to_string(limit) + " bytes";
        return false;
    }
    return true;
}

LabChild run_lab_child(const std::string& lab_binary, const nlohmann::json& job,
                       const std::string& backend, const ChildLimits& limits, const RunAsUser* user,
                       const ShaderCache& shader_cache) {
    LabChild child;
    child.dir = std::make_unique<WorkDir>(user);
    const std::string dir = child.dir->path();
    const std::string job_path = dir + "/JOB.json";
    {
        // Written while the directory is still course's: nothing of the
        // user's can have put a link in its place.
        std::ofstream out(job_path);
        if (!(out << job.dump() << "\n")) throw fw::Error("cannot write '" + job_path + "'");
    }
    std::vector<std::string> env;
    if (!shader_cache.dir.empty()) {
        std::string cache = shader_cache.dir;
        if (!shader_cache.shared) {
            cache = dir + "/shader-cache";
            std::error_code ec;
            std::filesystem::copy(shader_cache.dir, cache, std::filesystem::copy_options::recursive,
                                  ec);
            if (ec)
                throw fw::Error("cannot copy the shader cache '" + shader_cache.dir +
                                "' into the lab's work directory: " + ec.message());
        }
        // Mesa's cache (llvmpipe, and Mesa's GPU drivers) and NVIDIA's, both
        // in the copy; a driver that keeps neither compiles every shader.
        env = {"MESA_SHADER_CACHE_DIR=" + cache,       "MESA_DISK_CACHE_SINGLE_FILE=1",
               "MESA_SHADER_CACHE_DISABLE=false",      "__GL_SHADER_DISK_CACHE=1",
               "__GL_SHADER_DISK_CACHE_PATH=" + cache, "__GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1"};
    }
    child.dir->hand_over();
    std::vector<std::string> argv = {lab_binary, "grade-child", "--job", job_path, "--out", dir};
    if (!backend.empty()) argv.insert(argv.end(), {"--backend", backend});
    child.run = run_child(argv, dir, limits, user, env);
    child.outputs = std::make_unique<ChildOutputs>(dir, child.run, limits);
    if (child.run.ok() && !child.outputs->too_large().empty())
        child.run.status = LabStatus::failed(child.outputs->too_large());
    return child;
}

}  // namespace grading
