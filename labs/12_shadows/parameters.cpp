// Lab 12's parameter declarations (parameters.hpp).
#include "parameters.hpp"

namespace shadows {

std::vector<fw::Param> params() {
    return {
        fw::Param::choice(kScene, kScenes, Scene::Planar)
            .help("planar: two squares and their shadows flattened onto the ground; fog: four "
                  "planes at eye depths 2, 4, 6 and 8; shadowmap: a wall's shadow from a depth "
                  "map")
            .key('S'),
        fw::Param::choice(kLight, kLights, Light::Directional)
            .help("directional: towards (1, 1, 0); point: at (2, 4, 0) (planar)")
            .key('L'),
        fw::Param::boolean(kStencil, true)
            .help("the stencil lets each pixel be darkened once (planar)")
            .key('T'),
        fw::Param::number(kShadowAlpha, 0.5)
            .range(0.0, 1.0)
            .step(0.05)
            .help("the flattened shadow's alpha: the fraction of the ground's colour it takes "
                  "away (planar)")
            .key('A'),
        fw::Param::choice(kFog, kFogs, Fog::Linear)
            .help("the fog factor: none, linear from fog_start to fog_end, exp or exp2 with "
                  "fog_density (fog)")
            .key('F'),
        fw::Param::number(kFogDensity, 0.25)
            .range(0.0, 1.0)
            .step(0.05)
            .help("the density of exp and exp2 fog, per unit of distance (fog)")
            .key('D'),
        fw::Param::number(kFogStart, 1)
            .range(0.0, 4.0)
            .step(0.5)
            .help("linear fog: f = 1 at this distance and nearer (fog)")
            .key('N'),
        fw::Param::number(kFogEnd, 9)
            .range(5.0, 20.0)
            .step(0.5)
            .help("linear fog: f = 0 at this distance and farther: only the fog's colour (fog)")
            .key('E'),
        fw::Param::number(kBias, 0.02)
            .range(0.0, 0.2)
            .step(0.005)
            .help("subtracted from the fragment's light depth before the comparison (shadowmap)")
            .key('B'),
        fw::Param::boolean(kPcf, false)
            .help("percentage-closer filtering: GL_LINEAR on the depth comparison (shadowmap)")
            .key('P'),
    };
}

}  // namespace shadows
