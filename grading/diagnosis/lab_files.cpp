#include "grading/diagnosis/lab_files.hpp"

#include "grading/diagnosis/state_words.hpp"

namespace grading {

void read_diagnosis_files(LabFiles& lab) {
    std::vector<std::string> names;
    for (const fw::Checkpoint& cp : lab.file.checkpoints) names.push_back(cp.name);
    lab.mistake_frames = read_mistake_frames(lab.root, lab.dir, names);
    lab.parts = read_parts(lab.file);
    lab.state_words = read_state_words(lab.root, lab.dir, lab.file);
    check_part_places(lab.root, lab.file.path, lab.parts);
    read_starting_file(lab.root, lab.dir, lab.parts);
}

}  // namespace grading
