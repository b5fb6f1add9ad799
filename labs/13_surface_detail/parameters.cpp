// Lab 13's parameter declarations (parameters.hpp).
#include "parameters.hpp"

namespace surface_detail {

std::vector<fw::Param> params() {
    return {
        fw::Param::choice(kScene, kScenes, Scene::Bump)
            .help("bump: two flat squares with the same height map, their UVs turned 90 degrees "
                  "apart; envmap: a sphere in a cube map; raycast: a ray caster beside GL's "
                  "z-buffer")
            .key('S'),
        fw::Param::choice(kNormalsParam, kNormals, Normals::Bumped)
            .help("bumped: the normal map's normal in tangent space; interpolated: the vertex "
                  "normals alone (bump)")
            .key('N'),
        fw::Param::number(kBumpScale, 4)
            .range(0.0, 8.0)
            .step(0.5)
            .help("the height map's scale s in n = normalize(-s dh/du, -s dh/dv, 1) (bump)")
            .key('B'),
        fw::Param::choice(kEnv, kEnvs, Env::Fresnel)
            .help("reflect: the mirror; refract: glass, one surface; fresnel: both, mixed by "
                  "Schlick's F; normal: the cube map itself, read along the sphere's normal "
                  "(envmap)")
            .key('E'),
        fw::Param::number(kIor, 1.5)
            .range(1.0, 2.5)
            .step(0.05)
            .help("the sphere's index of refraction n2 (air n1 = 1): refract's ratio is n1 / n2 "
                  "(envmap)")
            .key('I'),
        fw::Param::choice(kView, kViews, View::Split)
            .help("split: the ray-cast image left, GL's right; cpu, gl: one of them; difference: "
                  "|cpu - gl| (raycast)")
            .key('V'),
        fw::Param::choice(kLightsParam, kLights, Lights::Two)
            .help("how many directional lights, each with its shadow rays (raycast)")
            .key('L'),
    };
}

}  // namespace surface_detail
