// Lab 7's parameter declarations (parameters.hpp).
#include "parameters.hpp"

namespace framebuffer_ops {

std::vector<fw::Param> params() {
    return {
        fw::Param::choice(kScene, kScenes, Scene::Blend)
            .help("blend: two translucent quads; sorting: three translucent panes in depth; "
                  "discard: a fence with holes; stencil: a mask and an outline; faces: an "
                  "open box; scissor: a clear and a draw limited to rectangles")
            .key('S'),
        fw::Param::choice(kMode, kModes, Mode::Over)
            .help("the blend mode of the two quads (blend)")
            .key('B'),
        fw::Param::choice(kFirst, kFirsts, First::A)
            .help("which quad is drawn first (blend)")
            .key('F'),
        fw::Param::boolean(kDepthWrite, true)
            .help("the panes write their depth (sorting)")
            .key('D'),
        fw::Param::boolean(kSorted, false)
            .help("the panes are drawn back to front, not near to far as listed (sorting)")
            .key('O'),
        fw::Param::boolean(kAlphaTest, true)
            .help("fragments with alpha below the cut-off are discarded (discard)")
            .key('A'),
        fw::Param::number(kCutoff, 0.5)
            .range(0.0, 1.0)
            .step(0.05)
            .help("the alpha below which a fragment is discarded (discard)")
            .key('C'),
        fw::Param::boolean(kOutline, true)
            .help("a white outline is drawn where the stencil is not set (stencil)")
            .key('L'),
        fw::Param::boolean(kCull, false).help("back faces are culled (faces)").key('U'),
        fw::Param::choice(kPattern, kPatterns, Pattern::Facing)
            .help("facing: outside orange, inside blue; primitive: grey by gl_PrimitiveID; "
                  "screen: squares in window pixels; object: cubes in object space (faces)")
            .key('P'),
        fw::Param::boolean(kScissor, true)
            .help("the clear and the draw are limited to their rectangles (scissor)")
            .key('X'),
    };
}

}  // namespace framebuffer_ops
