// `course prairielearn --out DIR` (docs/contract.md, `course prairielearn`):
// what a course needs for PrairieLearn's external grader, in two parts,
// because PrairieLearn pulls only public images:
// - image/: the grader's Docker build context, public: the Dockerfile
//   (grading/platforms/prairielearn/) and course/, the student version of the course
//   (`course release`) with setup.sh (grading/platforms/gradescope/) and the list of
//   student files with their student versions (as for Gradescope);
// - serverFilesCourse/gl-labs/: for the course's private repository: grade.sh
//   (grading/platforms/prairielearn/), the entrypoint, and every lab's checkpoints file
//   and references, hidden ones included, which `course autograde` grades
//   with, and each lab's unit cases (cases.json in its grading folder,
//   recorded for the autograder, hidden checks too, from the course seed): the
//   image's `course` has no references to draw them from; and
//   solution_shaders/NN_name/FILE, the course's own text of each student
//   shader, which `course grade` reads to tell which file is wrong (the
//   image holds only the student versions);
// - README.md: how to build the image, and each lab's question files.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "grading/diagnosis/file_isolation.hpp"
#include "grading/judge/cases.hpp"
#include "grading/judge/checks.hpp"
#include "grading/judge/course_seed.hpp"
#include "grading/platforms/autograder.hpp"
#include "grading/release/release.hpp"
#include "grading/run/repository.hpp"

namespace fs = std::filesystem;

namespace grading {

namespace {

constexpr const char* kTemplates = "grading/platforms/prairielearn";
constexpr const char* kFolder = "gl-labs";  // in serverFilesCourse/
constexpr const char* kImage = "ACCOUNT/gl-labs-grader";
// Random cases recorded per unit check, at most (each check's own count where lower).
constexpr int kMaxRandom = 200;

// What the folder will hold, read and checked before anything is written.
struct Plan {
    std::vector<std::string> files;  // of the repository
    StudentFiles students;
    std::vector<LabData> labs;
    std::vector<std::string> data;  // labs/*/checkpoints.json and labs/*/reference/*
    std::vector<std::pair<std::string, std::string>> cases;  // each lab's cases.json -> text
    unsigned seed = 0;                                       // the cases' seed
};

Plan plan_folder(const fs::path& source) {
    require_template(source, kTemplates, "grade.sh");
    require_template(source, kTemplates, "Dockerfile");
    require_template(source, "grading/platforms/gradescope", "setup.sh");
    Plan plan;
    plan.files = project_files(source.string());
    plan.students = student_files(source, plan.files);
    plan.labs = discover_labs(source.string());
    plan.seed = course_seed(source.string()).value;
    for (LabData& lab : plan.labs) {
        parse_checks(lab);
        const nlohmann::json cases =
            record_unit_cases(lab, plan.seed, kMaxRandom, RecordFor::Autograder);
        if (!cases.value("checks", nlohmann::json::array()).empty())
            plan.cases.emplace_back("labs/" + lab.dir + "/grading/cases.json", cases.dump() + "\n");
    }
    for (const std::string& rel : plan.files)
        for (const LabData& lab : plan.labs) {
            const std::string dir = "labs/" + lab.dir + "/";
            if ((rel == dir + "checkpoints.json" || rel.rfind(dir + "reference/", 0) == 0) &&
                fs::exists(fs::symlink_status(source / rel)))
                plan.data.push_back(rel);
        }
    return plan;
}

// The files of `lab` that students edit, by name: the names a question's
// file upload asks for.
std::vector<std::string> lab_student_files(const Plan& plan, const LabData& lab) {
    std::vector<std::string> names;
    for (const auto& [rel, text] : plan.students)
        if (rel.rfind("labs/" + lab.dir + "/", 0) == 0 ||
            rel.rfind("shaders/" + lab.dir + "/", 0) == 0)
            names.push_back(fs::path(rel).filename().string());
    return names;
}

// README.md: {IMAGE}, {FOLDER} and {LAB} stand for the image's name, the
// folder in serverFilesCourse and an example lab.
const char* const kReadme = R"(# PrairieLearn's external grader for the labs

Written by `course prairielearn`; write it again, and rebuild the image,
whenever the course changes: the image and the folder must come from the same
run. PrairieLearn pulls only public images, so the course is split in two.

- `image/`: the grader's image. It holds the student version of the course
  (`course release`: no solutions, no hidden checkpoints or their references),
  built in `/course` by the project's own `setup.sh`. Build it for
  PrairieLearn's machines, push it to a public registry, then sync it on the
  course's Sync page (Docker images):

      docker build --platform linux/amd64 -t {IMAGE} image
      docker push {IMAGE}

- `serverFilesCourse/{FOLDER}/`: copy it to the course repository's
  `serverFilesCourse/{FOLDER}/`, which students cannot read. It holds
  `grade.sh`, the entrypoint, and every lab's checkpoints file and references,
  hidden ones included, with the unit checks' cases (`labs/*/grading/cases.json`,
  drawn from the course's seed, labs/course_seed.json,
  so that every grading draws the same cases) and the course's own
  text of the shaders students edit (`solution_shaders/`, which tells a student
  which shader file is wrong): the image holds no reference code, since that
  would give the solutions away. The grader keeps this folder from the
  submitted code.

For each submission, `grade.sh LAB` puts the files in `/grade/student` in
place of the student versions (by name), builds `lab` as the user `student`,
grades LAB and writes `/grade/results/results.json` (docs/contract.md,
PrairieLearn's results.json). A submission that does not build is not
gradable: it counts neither points nor an attempt, and the compiler's message
is shown.

## One question per lab

The question's `info.json`, here for the lab `{LAB}`:

```json
"gradingMethod": "External",
"externalGradingOptions": {
  "enabled": true,
  "image": "{IMAGE}",
  "serverFilesCourse": ["{FOLDER}/"],
  "entrypoint": "/grade/serverFilesCourse/{FOLDER}/grade.sh {LAB}",
  "timeout": 300
}
```

and in its `question.html`, the files the students of that lab submit (FILES
in the table below):

```html
<pl-file-upload file-names="FILES"></pl-file-upload>
<pl-submission-panel>
  <pl-external-grader-results></pl-external-grader-results>
</pl-submission-panel>
```

| lab | entrypoint argument | FILES |
|-----|---------------------|-------|
)";

std::string replaced(std::string text, const std::string& name, const std::string& value) {
    for (size_t at = text.find(name); at != std::string::npos;
         at = text.find(name, at + value.size()))
        text.replace(at, name.size(), value);
    return text;
}

std::string readme(const Plan& plan) {
    std::string text = replaced(replaced(kReadme, "{IMAGE}", kImage), "{FOLDER}", kFolder);
    text = replaced(text, "{LAB}", plan.labs.empty() ? "LAB" : plan.labs.front().id);
    for (const LabData& lab : plan.labs) {
        std::string names;
        for (const std::string& name : lab_student_files(plan, lab))
            names += (names.empty() ? "" : ", ") + name;
        text += "| " + lab.dir + " | " + lab.id + " | " + names + " |\n";
    }
    return text;
}

// Writes the folder; returns how many solution shaders it holds.
size_t write_folder(const Plan& plan, const fs::path& source, const fs::path& dest) {
    const fs::path image = dest / "image", data = dest / "serverFilesCourse" / kFolder;
    release_tree(source.string(), (image / "course").string());
    write_file(image / "course" / "setup.sh",
               read_file(source / "grading/platforms/gradescope/setup.sh"), kExecutable);
    write_student_files(plan.students, image / "course");
    write_file(image / "Dockerfile", read_file(source / kTemplates / "Dockerfile"), kReadable);
    write_file(data / "grade.sh", read_file(source / kTemplates / "grade.sh"), kExecutable);
    for (const std::string& rel : plan.data) copy_entry(source / rel, data / rel);
    for (const auto& [rel, text] : plan.cases) write_file(data / rel, text, kReadable);
    const size_t shaders = write_solution_shaders(plan.students, source, data);
    write_file(dest / "README.md", readme(plan), kReadable);
    return shaders;
}

}  // namespace

int prairielearn_command(const std::string& out_dir) {
    const fs::path source(source_root()), dest(out_dir);
    require_new_output_dir(dest);
    const Plan plan = plan_folder(source);
    const size_t shaders = write_folder(plan, source, dest);
    std::printf("course prairielearn: PrairieLearn's grader for %s\n", source.string().c_str());
    std::printf("  %-40s the image: Dockerfile, course/ (the student version, %zu student files)\n",
                "image/", plan.students.size());
    std::printf("  %-40s grade.sh, and %zu checkpoints and reference files of %zu labs\n",
                ("serverFilesCourse/" + std::string(kFolder) + "/").c_str(), plan.data.size(),
                plan.labs.size());
    for (const auto& [rel, text] : plan.cases)
        std::printf("    %-38s the unit checks' cases, hidden ones too (seed %u, %zu bytes)\n",
                    rel.c_str(), plan.seed, text.size());
    std::printf("    %-38s the course's text of %zu student shaders (which file is wrong)\n",
                (std::string(kSolutionShaders) + "/").c_str(), shaders);
    std::printf("  %-40s how to build the image, and each lab's question\n", "README.md");
    std::printf(
        "Build and push the image from %s/image, and copy %s/serverFilesCourse/%s/ into the "
        "course repository (README.md says how).\n",
        out_dir.c_str(), out_dir.c_str(), kFolder);
    return 0;
}

}  // namespace grading
