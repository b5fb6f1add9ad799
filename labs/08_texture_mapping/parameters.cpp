// Lab 8's parameter declarations (parameters.hpp).
#include "parameters.hpp"

namespace texture_mapping {

std::vector<fw::Param> params() {
    return {
        fw::Param::choice(kScene, kScenes, Scene::Coordinates)
            .help("coordinates: a textured sphere; perspective: a floor, perspective-correct "
                  "(left) and affine (right); wrap: coordinates from -1 to 2; magnify: a 4 x 4 "
                  "texture on the whole frame; minify: a fine checkerboard made small; "
                  "lightmap: a base texture and a light map")
            .key('S'),
        fw::Param::choice(kMapping, kMappings, Mapping::Spherical)
            .help("where (s, t) comes from: stored per vertex, or computed per fragment by a "
                  "planar, cylindrical or spherical mapping (coordinates)")
            .key('M'),
        fw::Param::boolean(kImage, false)
            .help("the texture is the image file grid.png, not the checkerboard (coordinates)")
            .key('I'),
        fw::Param::boolean(kLit, false)
            .help("the texture is the diffuse colour of a lit surface (coordinates)")
            .key('L'),
        fw::Param::choice(kWrap, kWraps, Wrap::Repeat)
            .help("what coordinates outside [0, 1] read (wrap)")
            .key('W'),
        fw::Param::choice(kMagFilter, kMagFilters, MagFilter::Nearest)
            .help("the magnification filter (magnify)")
            .key('G'),
        fw::Param::choice(kMinFilter, kMinFilters, MinFilter::Nearest)
            .help("the minification filter (minify)")
            .key('N'),
        fw::Param::choice(kMaps, kMapsChoices, Maps::Modulate)
            .help("base: the base texture; light: the light map; modulate: their product "
                  "(lightmap)")
            .key('P'),
    };
}

}  // namespace texture_mapping
