// The lab API. A lab is a class with init() and draw() plus its parameter
// declaration, registered with one line:
//
//   FW_LAB(PipelineLab)   // at the end of labs/00_pipeline/pipeline_lab.cpp
//
// The lab's number, id and folder come from its folder's name, which the
// build passes to every file of the lab as FW_LAB_DIR: labs/02_robot_arm/
// is lab number 2, id `robot-arm` (underscores become hyphens), with its
// shaders in shaders/02_robot_arm/.
//
// The framework's runner owns main(), the context or window, the command line
// and the framebuffer; a lab only creates its GL objects and draws a frame.
#pragma once

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "framework/params.hpp"
#include "framework/units.hpp"

namespace fw {

class Program;
class ShaderError;

// A lab's description. The lab fills in its title, parameters, controls and
// functions; registration fills in number, id and dir from the folder name:
// `id` is what users type (`lab render pipeline`), `dir` the folder under
// labs/ and shaders/ (e.g. "00_pipeline").
struct LabInfo {
    int number = 0;
    std::string id;
    std::string dir;
    std::string title;
    std::vector<Param> params;
    std::vector<std::string> controls;    // extra window controls, e.g. "drag: orbit the eye"
    std::vector<UnitFunction> functions;  // student functions the grader evaluates (units.hpp)
    // The width / height the scene is drawn for; 0: the lab's projection
    // follows the frame's aspect. A fixed aspect holds in any frame (`lab
    // render --size`, the window, `lab serve`): the lab draws into the largest
    // centred viewport of that aspect and the rest stays black, letterboxed,
    // never stretched.
    double aspect = 0.0;
};

// The lab's programs, loaded from files under shaders/. The library owns them
// so that the window can reload them all from disk (R): a program that fails
// to compile keeps its last good version and the error is shown.
class ProgramLibrary {
public:
    // `folder`: the lab's folder under shaders/ (its LabInfo::dir), where
    // load() looks for file names without a '/'; empty: shaders/ itself.
    explicit ProgramLibrary(std::string folder = {});
    ~ProgramLibrary();
    ProgramLibrary(const ProgramLibrary&) = delete;
    ProgramLibrary& operator=(const ProgramLibrary&) = delete;

    // Compiles and links now: load({"pipeline.vert", "pipeline.frag"}). A name
    // without '/' is in the lab's folder; one with '/' is relative to
    // shaders/ (or absolute). `feedback`: the outputs transform feedback
    // captures (Program::from_files). A program that does not build is kept as
    // failed (Program::failed): whatever draws with it throws the
    // fw::ShaderError, with file, stage, line and source, and the rest of the
    // lab still draws. The reference stays valid for the library's life.
    Program& load(const std::vector<std::string>& files,
                  const std::vector<std::string>& feedback = {});
    // Recompiles every program. Returns one message per program that failed
    // (those keep drawing with their last good version, or stay failed);
    // empty when all built.
    std::vector<std::string> reload_all();
    // The programs that have not built, in the order they were loaded.
    std::vector<const ShaderError*> build_errors() const;

private:
    std::string folder_;
    std::vector<std::unique_ptr<Program>> programs_;
};

// A buffer the lab's shaders wrote (transform feedback, a compute shader),
// read back as floats for the grader's `buffer` checks (docs/contract.md).
struct LabBuffer {
    std::string name;           // what checks call it, e.g. "particles"
    int components = 1;         // floats per element: 3 for a vec3 per particle
    std::vector<float> values;  // element after element, `components` floats each
};

// What a frame is drawn into.
struct Frame {
    int width = 512;
    int height = 512;
    double time = 0.0;  // seconds since the window opened; 0 offscreen
};

// Where a scene of `aspect` (LabInfo::aspect) goes in a frame of width x
// height: the whole frame for 0, else the largest centred rectangle of that
// aspect.
struct Viewport {
    int x = 0, y = 0, width = 0, height = 0;
};
Viewport scene_viewport(double aspect, int width, int height);
// `frame` as the lab sees it: the size of its scene_viewport.
Frame scene_frame(const LabInfo& info, const Frame& frame);

class Lab {
public:
    virtual ~Lab() = default;
    // Creates buffers, vertex arrays and programs. Called once, with a current
    // context, before the first draw.
    virtual void init(ProgramLibrary& programs) = 0;
    // Draws one frame into the bound framebuffer. The runner has set the
    // viewport to the frame (the scene's part of it, for a lab with a fixed
    // LabInfo::aspect: `frame` then gives that part's size) and cleared colour
    // to (0, 0, 0, 1) and depth to 1.
    virtual void draw(const ParamValues& params, const Frame& frame) = 0;
    // Extra figures for --stats (under "lab_stats"), e.g. bytes stored, for
    // the frame just drawn with these parameters.
    virtual nlohmann::json stats(const ParamValues&, const Frame&) const {
        return nlohmann::json::object();
    }
    // The buffers the frame just drawn with these parameters wrote, read
    // back, for `buffer` checks; called after draw(), in its context.
    virtual std::vector<LabBuffer> buffers(const ParamValues&, const Frame&) const { return {}; }
    // Checks that involve several parameters (e.g. far > near); returns an
    // error message naming them, or empty when the values are consistent.
    virtual std::string validate(const ParamValues&) const { return {}; }
    // The window and the browser page only: mouse drag in pixels of `frame`
    // (dy > 0 when the mouse moves up, as GL's y) and scroll steps, for
    // controls such as an orbit camera. May change parameters; return true
    // if it did (the change is kept only if validate() accepts it).
    virtual bool on_drag(ParamValues&, const Frame&, double /*dx*/, double /*dy*/) { return false; }
    virtual bool on_scroll(ParamValues&, const Frame&, double /*steps*/) { return false; }
};

using LabFactory = std::function<std::unique_ptr<Lab>()>;

struct RegisteredLab {
    LabInfo info;
    LabFactory create;
};

// Registers a lab from the folder `dir` ("02_robot_arm"): fills in info's
// number, id and dir, and checks the declaration. FW_LAB calls it.
bool register_lab(std::string_view dir, LabInfo info, LabFactory factory);
// "02_robot_arm" -> number 2, id "robot-arm"; throws fw::Error for a name
// that is not NN_name.
void parse_lab_dir(std::string_view dir, int& number, std::string& id);
// All labs, sorted by number.
const std::vector<RegisteredLab>& registered_labs();
// The registered lab with that id; throws UsageError listing the valid names.
// The registry owns every lab for the life of the program. The id is taken as
// a view, not a reference, so that a temporary argument (a literal, a JSON
// value) cannot look like what the returned reference points into.
const RegisteredLab& find_lab(std::string_view id);
// The registered lab of folder `dir` ("00_pipeline"); throws like find_lab.
const RegisteredLab& find_lab_in_folder(std::string_view dir);
// Default values with validation of the declaration itself.
ParamValues default_params(const RegisteredLab& lab);
// Path of a file in the lab's folder, e.g. lab_path(info, "checkpoints.json").
std::string lab_path(const LabInfo& info, const std::string& file);

}  // namespace fw

#ifndef FW_LAB_DIR
#define FW_LAB_DIR ""  // only labs/NN_name/*.cpp get the folder; FW_LAB checks it
#endif

// Registers `Class`, which must have `static fw::LabInfo info();`, as the lab
// of the folder this file is in.
#define FW_LAB(Class)                                                                            \
    namespace {                                                                                  \
    static_assert(sizeof(FW_LAB_DIR) > 1,                                                        \
                  "FW_LAB is only for files in labs/NN_name/: the build "                        \
                  "passes their folder's name as FW_LAB_DIR");                                   \
    const bool fw_lab_registered_##Class =                                                       \
        ::fw::register_lab(FW_LAB_DIR, Class::info(), [] { return std::make_unique<Class>(); }); \
    }
