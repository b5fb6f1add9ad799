// The labs course grades: every labs/NN_name/checkpoints.json of a
// repository, and the ones a command line names.
#include <filesystem>
#include <set>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/judge/checks.hpp"
#include "grading/run/repository.hpp"

namespace grading {

namespace fs = std::filesystem;

std::vector<LabData> discover_labs(const std::string& root) {
    const fs::path labs_dir = fs::path(root) / "labs";
    if (!fs::is_directory(labs_dir))
        throw fw::UsageError(
            "no labs/ folder in '" + root +
            "'; set LAB_ROOT to the repository that holds labs/NN_name/checkpoints.json");
    std::set<std::string> folders;
    for (const fs::directory_entry& e : fs::directory_iterator(labs_dir))
        if (e.is_directory() && fs::exists(e.path() / "checkpoints.json"))
            folders.insert(e.path().filename().string());
    std::vector<LabData> labs;
    for (const std::string& folder : folders) {
        LabData lab;
        lab.root = root;
        lab.sources = sources_root(root);
        lab.dir = folder;
        lab.file = fw::read_checkpoint_file((labs_dir / folder / "checkpoints.json").string());
        lab.id = lab.file.lab;
        for (const LabData& other : labs)
            if (other.id == lab.id)
                throw fw::UsageError(lab.file.path + ": \"lab\" is \"" + lab.id + "\", as in " +
                                     other.file.path + "; each lab needs its own name");
        labs.push_back(std::move(lab));
    }
    return labs;
}

std::vector<LabData> select_labs(const std::vector<LabData>& all,
                                 const std::vector<std::string>& names) {
    if (names.empty()) return all;
    const std::string known = fw::join(all, ", ", &LabData::id);
    std::set<std::string> wanted;
    for (const std::string& name : names) {
        bool found = false;
        for (const LabData& lab : all) found = found || lab.id == name || lab.dir == name;
        if (!found)
            throw fw::UsageError("unknown lab '" + name +
                                 "'; the labs are: " + (known.empty() ? "(none)" : known));
        wanted.insert(name);
    }
    std::vector<LabData> out;
    for (const LabData& lab : all)
        if (wanted.count(lab.id) || wanted.count(lab.dir)) out.push_back(lab);
    return out;
}

}  // namespace grading
