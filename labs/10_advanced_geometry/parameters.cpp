// Lab 10's parameter declarations (parameters.hpp).
#include "parameters.hpp"

namespace advanced_geometry {

std::vector<fw::Param> params() {
    return {
        fw::Param::choice(kScene, kScenes, Scene::Instances)
            .help("instances: a grid of quads from one instanced draw; clip: a sphere cut by a "
                  "user clip plane; layers: one draw into the six faces of a cube map, shown "
                  "unfolded; silhouette: a cube's outline found from adjacency")
            .key('S'),
        fw::Param::integer(kColumns, 5)
            .range(1, kMaxCells)
            .help("columns of the grid (instances)")
            .key('C'),
        fw::Param::integer(kRows, 4)
            .range(1, kMaxCells)
            .help("rows of the grid (instances)")
            .key('W'),
        fw::Param::number(kClipAngle, 30)
            .range(-180, 180)
            .unit("deg")
            .step(15)
            .help("the clip plane's normal, turned from +x towards +y (clip)")
            .key('A'),
        fw::Param::number(kClipOffset, 0.25f)
            .range(-1, 1)
            .step(0.05f)
            .help("the clip plane's d: the sphere is kept where n . p + d >= 0 (clip)")
            .key('D'),
        fw::Param::integer(kFaceSize, 128)
            .range(8, 256)
            .step(8)
            .help("texels along a side of each cube-map face (layers)")
            .key('F'),
        fw::Param::number(kYaw, 30)
            .range(-180, 180)
            .unit("deg")
            .step(10)
            .help("the cube's turn about y (silhouette)")
            .key('Y'),
        fw::Param::number(kPitch, 25)
            .range(-90, 90)
            .unit("deg")
            .step(10)
            .help("the cube's tilt about x, after the turn (silhouette)")
            .key('P'),
    };
}

}  // namespace advanced_geometry
