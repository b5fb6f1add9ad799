// Lab 9's parameter declarations (parameters.hpp).
#include "parameters.hpp"

#include "particles.hpp"
#include "subdivide.hpp"

namespace buffers {

std::vector<fw::Param> params() {
    return {
        fw::Param::choice(kScene, kScenes, Scene::Feedback)
            .help("feedback: particles advanced by transform feedback; compute: the same by a "
                  "compute shader; subdivide: a sphere made by feeding a geometry shader's "
                  "triangles back; block: a lit ellipsoid whose matrices are a uniform block")
            .key('S'),
        fw::Param::integer(kCount, 100)
            .range(1, kMaxParticles)
            .step(10)
            .help("particles (feedback, compute)")
            .key('N'),
        fw::Param::integer(kSteps, 40)
            .range(0, 100)
            .step(5)
            .help("time steps of 0.02 s (feedback, compute)")
            .key('T'),
        fw::Param::integer(kPasses, 2)
            .range(0, kMaxPasses)
            .help("subdivision passes, each turning a triangle into four (subdivide)")
            .key('P'),
        fw::Param::number(kAngle, 40)
            .range(-180, 180)
            .unit("deg")
            .step(15)
            .help("the ellipsoid's turn about y (block)")
            .key('A'),
    };
}

}  // namespace buffers
