// Every hidden variation has a visible sibling: for each hidden checkpoint of a
// lab and each parameter it sets to a value other than the lab's default, some
// visible checkpoint of the same lab sets that parameter to a value other than
// its default too. A student part that ignores a parameter (an alpha test that
// keeps its own cut-off) then fails a visible checkpoint, which the student
// sees before the deadline, and not only a hidden one. Values compare as
// `--set` writes them, after the lab's declaration has resolved them. The
// labs' declarations are linked in (no GL); the checkpoints are read from the
// source tree. The rule: docs/conventions.md, Student parts.
#include <map>
#include <set>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"
#include "framework/lab.hpp"
#include "tests/support/test_support.hpp"

namespace {

// "lab-id/parameter" -> why a hidden checkpoint may vary it alone: the lab's
// own code reads it, and no student part does, so no student part can ignore
// it.
const std::map<std::string, std::string> kExempt = {
    {"pipeline/yaw", "the cube's turn, made by cube_mvp() in scenes.cpp"},
    {"pipeline/pitch", "the cube's turn, made by cube_mvp() in scenes.cpp"},
    {"geometry/spin",
     "the model matrix, applied by mesh.vert and to the offset by geometry.cpp; the geometry "
     "shaders see world space only"},
    {"interpolation/subdiv", "the icosphere the lab builds; the shaders see its vertices"},
    {"framebuffer-ops/outline",
     "the lab leaves the outline's draw out; draw_where_unmarked() is not called"},
    {"framebuffer-ops/scissor", "the lab calls scissor_to() only when it is on"},
    {"buffers/passes", "subdivide() in subdivide.cpp repeats the passes; subdivide.geom does one"},
    {"buffers/angle", "the ellipsoid's turn, in the matrices the lab hands pack_scene()"},
    {"advanced-geometry/face_size", "the size of the cube map the lab makes"},
    {"advanced-geometry/yaw",
     "the cube's turn, in the matrix the lab makes; silhouette.geom sees clip space only"},
    {"advanced-geometry/pitch",
     "the cube's turn, in the matrix the lab makes; silhouette.geom sees clip space only"},
};

// The parameters that `cp` sets to a value other than the lab's default.
std::vector<std::string> varied(const fw::RegisteredLab& lab, const fw::Checkpoint& cp) {
    const fw::ParamValues defaults = fw::default_params(lab);
    const fw::ParamValues values = fw::checkpoint_params(lab, cp);
    std::vector<std::string> out;
    for (const auto& item : cp.params.items())
        if (values.text(item.key()) != defaults.text(item.key())) out.push_back(item.key());
    return out;
}

}  // namespace

TEST_CASE("each parameter a hidden checkpoint varies, a visible checkpoint varies too") {
    int hidden = 0;
    std::set<std::string> exempt_used;
    for (const fw::RegisteredLab& lab : fw::registered_labs()) {
        const std::vector<fw::Checkpoint> all = fw::load_checkpoints(lab);
        std::set<std::string> visible;  // the parameters some visible checkpoint varies
        for (const fw::Checkpoint& cp : all)
            if (cp.visibility == "visible")
                for (const std::string& name : varied(lab, cp)) visible.insert(name);
        const fw::ParamValues defaults = fw::default_params(lab);
        for (const fw::Checkpoint& cp : all) {
            if (cp.visibility != "hidden") continue;
            ++hidden;
            const fw::ParamValues values = fw::checkpoint_params(lab, cp);
            for (const std::string& name : varied(lab, cp)) {
                if (visible.count(name)) continue;
                if (kExempt.count(lab.info.id + "/" + name)) {
                    exempt_used.insert(lab.info.id + "/" + name);
                    continue;
                }
                FAIL_CHECK(fw::lab_path(lab.info, "checkpoints.json")
                           << ": hidden `" << cp.name << "` sets " << name << "="
                           << values.text(name) << " (default " << defaults.text(name)
                           << "), and no visible checkpoint sets " << name
                           << " to another value than its default: add a visible sibling "
                              "that does, with another value than the hidden one's");
            }
        }
    }
    MESSAGE(hidden << " hidden checkpoints of " << fw::registered_labs().size() << " labs");
    CHECK(fw::registered_labs().size() >= 11);
    CHECK(hidden > 10);
    // An exemption no hidden checkpoint needs any more is dropped from the list.
    for (const auto& [key, why] : kExempt)
        if (!exempt_used.count(key))
            FAIL_CHECK("kExempt's " << key << " (" << why
                                    << ") is varied by no hidden checkpoint alone: drop it");
}
