// The lab API. A lab is a class with init() and draw() plus its parameter
// declaration, registered with one line:
//
//   FW_LAB(PipelineLab)   // at the end of labs/00_pipeline/pipeline.cpp
//
// The framework's runner owns main(), the context or window, the command line
// and the framebuffer; a lab only creates its GL objects and draws a frame.
#pragma once

#include <nlohmann/json.hpp>

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "framework/params.hpp"
#include "framework/units.hpp"

namespace fw {

class Program;

// A lab's description: `id` is what users type (`lab render pipeline`),
// `dir` its folder under labs/ and shaders/ (e.g. "00_pipeline").
struct LabInfo {
    int number = 0;
    std::string id;
    std::string dir;
    std::string title;
    std::vector<Param> params;
    std::vector<std::string> controls;  // extra window controls, e.g. "drag: orbit the eye"
    std::vector<UnitFunction> functions;  // student functions the grader evaluates (units.hpp)
};

// The lab's programs, loaded from files under shaders/. The library owns them
// so that the window can reload them all from disk (R): a program that fails
// to compile keeps its last good version and the error is shown.
class ProgramLibrary {
public:
    ProgramLibrary();
    ~ProgramLibrary();
    ProgramLibrary(const ProgramLibrary&) = delete;
    ProgramLibrary& operator=(const ProgramLibrary&) = delete;

    // Compiles and links now; throws fw::Error with file, stage, line and
    // source on failure. The reference stays valid for the library's life.
    Program& load(const std::vector<std::string>& files);
    // Recompiles every program. Returns one message per program that failed
    // (those keep drawing with their last good version); empty when all built.
    std::vector<std::string> reload_all();

private:
    std::vector<std::unique_ptr<Program>> programs_;
};

// What a frame is drawn into.
struct Frame {
    int width = 512;
    int height = 512;
    double time = 0.0;  // seconds since the window opened; 0 offscreen
};

class Lab {
public:
    virtual ~Lab() = default;
    // Creates buffers, vertex arrays and programs. Called once, with a current
    // context, before the first draw.
    virtual void init(ProgramLibrary& programs) = 0;
    // Draws one frame into the bound framebuffer. The runner has set the
    // viewport to the frame and cleared colour to (0, 0, 0, 1) and depth to 1.
    virtual void draw(const ParamValues& params, const Frame& frame) = 0;
    // Extra figures for --stats (under "lab_stats"), e.g. bytes stored.
    virtual nlohmann::json stats(const ParamValues&) const { return nlohmann::json::object(); }
    // Checks that involve several parameters (e.g. far > near); returns an
    // error message naming them, or empty when the values are consistent.
    virtual std::string validate(const ParamValues&) const { return {}; }
    // Window only: mouse drag in pixels (dy > 0 when the mouse moves up, as
    // GL's y) and scroll steps, for controls such as an orbit camera. May
    // change parameters; return true if it did.
    virtual bool on_drag(ParamValues&, double /*dx*/, double /*dy*/) { return false; }
    virtual bool on_scroll(ParamValues&, double /*steps*/) { return false; }
};

using LabFactory = std::function<std::unique_ptr<Lab>()>;

struct RegisteredLab {
    LabInfo info;
    LabFactory create;
};

bool register_lab(LabInfo info, LabFactory factory);
// All labs, sorted by number.
const std::vector<RegisteredLab>& registered_labs();
// The registered lab with that id; throws UsageError listing the valid names.
// The registry owns every lab for the life of the program. The id is taken as
// a view, not a reference, so that a temporary argument (a literal, a JSON
// value) cannot look like what the returned reference points into.
const RegisteredLab& find_lab(std::string_view id);
// Default values with validation of the declaration itself.
ParamValues default_params(const RegisteredLab& lab);
// Path of a file in the lab's folder, e.g. lab_path(info, "checkpoints.json").
std::string lab_path(const LabInfo& info, const std::string& file);

}  // namespace fw

// Registers `Class`, which must have `static fw::LabInfo info();`.
#define FW_LAB(Class)                                               \
    namespace {                                                     \
    const bool fw_lab_registered_##Class = ::fw::register_lab(      \
        Class::info(), [] { return std::make_unique<Class>(); });   \
    }
