// Draws frames of one lab offscreen, in the current context, into a
// framework-owned framebuffer, and reads back colour, depth and stats.
// `lab render`, the tests and the grading child all draw through this.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "framework/context.hpp"
#include "framework/image.hpp"
#include "framework/lab.hpp"

namespace fw {

class Framebuffer;
class Query;

struct RenderOutput {
    Image color;
    DepthImage depth;
    nlohmann::json stats;  // the --stats fields (docs/contract.md, `--stats FILE.json`)
};

class LabRenderer {
public:
    // Creates the lab and calls its init(); throws what init throws.
    LabRenderer(const RegisteredLab& lab, ContextInfo context);
    ~LabRenderer();
    LabRenderer(const LabRenderer&) = delete;
    LabRenderer& operator=(const LabRenderer&) = delete;

    // One frame at width x height; throws UsageError for a size of zero or
    // above the GL limit, or parameters the lab rejects. `time`: seconds for
    // a lab that animates (Frame::time; 0 draws what lab render draws).
    // Without `with_depth` the depth is not read back (RenderOutput::depth
    // stays empty).
    RenderOutput render(const ParamValues& params, int width, int height, double time = 0.0,
                        bool with_depth = true);

    Lab& lab() { return *lab_; }
    // The lab's programs, those that failed to build included.
    const ProgramLibrary& programs() const { return programs_; }
    ProgramLibrary& programs() { return programs_; }

private:
    const RegisteredLab& registered_;
    ContextInfo context_;
    ProgramLibrary programs_;
    std::unique_ptr<Lab> lab_;
    std::unique_ptr<Framebuffer> framebuffer_;
    // Created once, begun and ended around every frame's draw.
    std::unique_ptr<Query> primitives_, elapsed_;
};

// "512x384" -> (512, 384); throws UsageError.
void parse_size(const std::string& text, int& width, int& height);

}  // namespace fw
