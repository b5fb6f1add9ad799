#include "grading/platforms/compile_units.hpp"

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
#include "grading/platforms/submitted_files.hpp"
#include "grading/release/release.hpp"

namespace grading {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kBuildSeconds = 300;
constexpr rlim_t kBuildMemory = rlim_t(4) << 30;

double cpu_of(const rusage& u) {
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

std::string without_werror(std::string command) {
    for (size_t at; (at = command.find(" -Werror ")) != std::string::npos;)
        command.erase(at, std::string(" -Werror").size());
    return command;
}

}  // namespace

CompileCommands::CompileCommands(const fs::path& build, const std::string& root) {
    const json db = json::parse(read_file(build / "compile_commands.json"));
    for (const json& e : db) {
        const std::string file = e.value("file", "");
        if (file.rfind(root + "/", 0) != 0 || !e.contains("command")) continue;
        Unit u;
        u.directory = e.value("directory", "");
        u.command = e["command"];
        u.source = file;
        const size_t o = u.command.find(" -o "), c = u.command.find(" -c ");
        if (o == std::string::npos || c == std::string::npos) continue;
        u.object = u.command.substr(o + 4, u.command.find(' ', o + 4) - (o + 4));
        units_[file.substr(root.size() + 1)] = u;
    }
}

const CompileCommands::Unit& CompileCommands::unit(const std::string& rel) const {
    const auto found = units_.find(rel);
    if (found == units_.end()) throw fw::UsageError("the build has no compile command for " + rel);
    return found->second;
}

std::string CompileCommands::command(const std::string& rel, const std::string& source,
                                     const std::string& object) const {
    const Unit& u = unit(rel);
    std::string command = without_werror(u.command);
    command = replace_in_command(command, " -o " + u.object + " ",
                                 " -o " + fw::shell_quote(object) + " ", rel);
    return replace_in_command(command, " -c " + u.source, " -c " + fw::shell_quote(source), rel);
}

bool run_build_command(const std::string& command, const std::string& dir, const fs::path& log,
                       double& cpu, bool memory_cap) {
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

std::string replace_in_command(std::string text, const std::string& from, const std::string& to,
                               const std::string& what) {
    const size_t at = text.find(from);
    if (at == std::string::npos)
        throw fw::UsageError("the build's command for " + what + " has no '" + from +
                             "': build `lab` again with this project's CMake (Makefile "
                             "generator)");
    return text.replace(at, from.size(), to);
}

std::string first_error(const std::string& log) {
    std::istringstream lines(log);
    for (std::string line; std::getline(lines, line);)
        if (line.find("error") != std::string::npos || line.find("fatal") != std::string::npos)
            return line;
    return "";
}

std::string without_folder(std::string log, const std::string& folder) {
    const std::string prefix = folder + "/";
    for (size_t at; (at = log.find(prefix)) != std::string::npos;) log.erase(at, prefix.size());
    return log;
}

std::string lab_folder(const std::string& rel) {
    if (rel.rfind("labs/", 0) != 0) return "";
    const size_t end = rel.find('/', 5);
    return end == std::string::npos ? "" : rel.substr(5, end - 5);
}

std::map<std::string, std::string> labs_not_compiling(const fs::path& source,
                                                      const std::vector<std::string>& files,
                                                      const fs::path& versions,
                                                      const std::string& prefix,
                                                      const fs::path& work) {
    std::map<std::string, std::string> failed;
    if (!fs::exists(source / "build" / "compile_commands.json")) return failed;  // no lab to blame
    const std::string root = fs::weakly_canonical(source).string();
    const CompileCommands commands(source / "build", root);
    for (const std::string& rel : files) {
        const std::string lab = lab_folder(rel);
        if (lab.empty() || fs::path(rel).extension() != ".cpp" || !commands.knows(rel) ||
            same_contents(source / rel, versions / rel))
            continue;
        const fs::path log = work / "compile.log";
        std::error_code ec;
        fs::remove(log, ec);
        double cpu = 0;
        if (run_build_command(prefix + commands.command(rel, commands.source(rel), "/dev/null"),
                              commands.directory(rel), log, cpu, /*memory_cap=*/true))
            continue;
        failed[lab] += without_folder(fs::exists(log) ? read_file(log) : "", root);
    }
    return failed;
}

}  // namespace grading
