#include "grading/class/build_lab.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/class/content_hash.hpp"
#include "grading/commands/lab_sources.hpp"
#include "grading/release/release.hpp"
#include "grading/report/report_text.hpp"

namespace grading::cls {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Limits of one compiler or linker run: a submission that makes the
// compiler loop or swell fails its own build, nothing else.
constexpr int kBuildSeconds = 300;
constexpr rlim_t kBuildMemory = rlim_t(4) << 30;

double cpu_of(const rusage& u) {
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

// Runs `command` with /bin/sh in `dir`, its output appended to `log`;
// true when it exits 0 within the limits (RLIMIT_AS only with
// `memory_cap`). Its CPU time is added to `cpu` (a linker's child that it
// does not wait for, as mold's, is not counted).
bool run_shell(const std::string& command, const std::string& dir, const fs::path& log, double& cpu,
               bool memory_cap) {
    const pid_t pid = fork();
    if (pid < 0) throw fw::Error("cannot start the compiler: fork failed");
    if (pid == 0) {
        setpgid(0, 0);
        const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0600);
        const int null = open("/dev/null", O_RDONLY);
        if (fd < 0 || null < 0 || chdir(dir.c_str()) != 0) _exit(127);
        dup2(null, 0);
        dup2(fd, 1);
        dup2(fd, 2);
        const rlimit memory{kBuildMemory, kBuildMemory};
        const rlimit seconds{kBuildSeconds, kBuildSeconds};
        if (memory_cap) setrlimit(RLIMIT_AS, &memory);
        setrlimit(RLIMIT_CPU, &seconds);
        execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    const auto start = std::chrono::steady_clock::now();
    int status = 0;
    rusage used{};
    for (;;) {
        const pid_t done = wait4(pid, &status, WNOHANG, &used);
        if (done == pid) break;
        if (std::chrono::steady_clock::now() - start > std::chrono::seconds(kBuildSeconds)) {
            kill(-pid, SIGKILL);
            wait4(pid, &status, 0, &used);
            cpu += cpu_of(used);
            std::ofstream(log, std::ios::app)
                << "\nstopped after " << kBuildSeconds << " s: the build took too long\n";
            return false;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    kill(-pid, SIGKILL);  // whatever it left behind
    cpu += cpu_of(used);
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// `text` with its one occurrence of `from` replaced by `to`; throws with
// `what` when `from` is not there.
std::string replace_once(std::string text, const std::string& from, const std::string& to,
                         const std::string& what) {
    const size_t at = text.find(from);
    if (at == std::string::npos)
        throw fw::UsageError("the build's command for " + what + " has no '" + from +
                             "': build `lab` again with this project's CMake (Makefile "
                             "generator)");
    return text.replace(at, from.size(), to);
}

std::string without_werror(std::string command) {
    for (size_t at; (at = command.find(" -Werror ")) != std::string::npos;)
        command.erase(at, std::string(" -Werror").size());
    return command;
}

std::string first_error(const std::string& log) {
    std::istringstream lines(log);
    for (std::string line; std::getline(lines, line);)
        if (line.find("error") != std::string::npos || line.find("fatal") != std::string::npos)
            return line;
    return "";
}

}  // namespace

LabBuilder::LabBuilder(const std::string& lab_binary, fs::path objects)
    : objects_(std::move(objects)) {
    const LabSources sources = lab_sources(lab_binary);
    if (sources.manifest.empty())
        throw fw::UsageError("'" + lab_binary +
                             "' has no LAB.sources beside it: grade-class builds each "
                             "submission against a `lab` this project's CMake built");
    root_ = sources.source;
    const fs::path build(sources.build);
    const json db = json::parse(read_file(build / "compile_commands.json"));
    for (const json& e : db) {
        const std::string file = e.value("file", "");
        if (file.rfind(root_ + "/", 0) != 0 || !e.contains("command")) continue;
        Unit u;
        u.directory = e.value("directory", "");
        u.command = e["command"];
        u.source = file;
        const size_t o = u.command.find(" -o "), c = u.command.find(" -c ");
        if (o == std::string::npos || c == std::string::npos) continue;
        u.object = u.command.substr(o + 4, u.command.find(' ', o + 4) - (o + 4));
        units_[file.substr(root_.size() + 1)] = u;
    }
    link_dir_ = (build / "labs").string();
    std::string link = read_file(build / "labs" / "CMakeFiles" / "lab.dir" / "link.txt");
    while (!link.empty() && (link.back() == '\n' || link.back() == ' ')) link.pop_back();
    link_command_ = link;
    const size_t o = link.find(" -o ");
    if (o == std::string::npos)
        throw fw::UsageError("the link command of `lab` in " + build.string() + " names no -o");
    link_output_ = link.substr(o + 4, link.find(' ', o + 4) - (o + 4));
    fs::create_directories(objects_);
}

BuiltLab LabBuilder::build(const std::map<std::string, fs::path>& cpp, const fs::path& work,
                           const fs::path& out) const {
    BuiltLab b;
    const fs::path log = work / "build.log";
    fs::create_directories(work);
    fs::remove(log);
    std::string link = link_command_;
    bool ok = true;
    for (const auto& [rel, from] : cpp) {
        const auto unit = units_.find(rel);
        if (unit == units_.end())
            throw fw::UsageError("the build has no compile command for " + rel);
        const Unit& u = unit->second;
        const std::string text = read_file(from);
        if (text == read_file(u.source)) continue;  // the course's own object stands
        const fs::path source = work / rel;
        fs::create_directories(source.parent_path());
        report::write_text_file(source.string(), text);
        std::string command = without_werror(u.command);
        const fs::path object =
            objects_ / (content_hash(command + '\0' + rel + '\0' + text) + ".o");
        if (!fs::exists(object)) {
            const fs::path partial = object.string() + ".part" + std::to_string(getpid());
            command = replace_once(command, " -o " + u.object + " ",
                                   " -o " + fw::shell_quote(partial.string()) + " ", rel);
            command = replace_once(command, " -c " + u.source,
                                   " -c " + fw::shell_quote(source.string()), rel);
            ++b.compiled;
            if (!run_shell(command, u.directory, log, b.cpu_seconds, /*memory_cap=*/true)) {
                ok = false;
                continue;
            }
            fs::rename(partial, object);
        }
        link = replace_once(link, " " + u.object + " ",
                            " " + fw::shell_quote(object.string()) + " ", rel + " (link)");
    }
    if (ok) {
        link = replace_once(link, " -o " + link_output_ + " ",
                            " -o " + fw::shell_quote(out.string()) + " ", "lab (link)");
        // The linker's address space is not capped: mold reserves far more
        // than it uses (its allocator's arenas), and the course's objects
        // make most of what it links.
        ok = run_shell(link, link_dir_, log, b.cpu_seconds, /*memory_cap=*/false);
    }
    b.log = fs::exists(log) ? read_file(log) : "";
    // The student's paths as in their repository, not in the work folder.
    const std::string prefix = work.string() + "/";
    for (size_t at; (at = b.log.find(prefix)) != std::string::npos;) b.log.erase(at, prefix.size());
    b.first_error = first_error(b.log);
    b.ok = ok;
    return b;
}

}  // namespace grading::cls
