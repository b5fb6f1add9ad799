// Lab 8's textures (textures.hpp), and the image file read with stb_image.
#include "textures.hpp"

#include <stb/stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>

#include "framework/error.hpp"

namespace texture_mapping {

namespace {

// A width x height image whose texel (i, j) is color(i, j); j = 0 is the bottom row.
fw::Image make(int width, int height, const std::function<glm::vec3(int, int)>& color) {
    fw::Image img(width, height);
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) img.at(i, j) = texel(color(i, j));
    return img;
}

glm::vec3 checker(int i, int j, glm::vec3 even, glm::vec3 odd) {
    return (i + j) % 2 == 0 ? even : odd;
}

}  // namespace

fw::Rgba8 texel(glm::vec3 color) {
    const auto byte = [](float v) {
        return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    };
    return {byte(color.r), byte(color.g), byte(color.b), 255};
}

fw::Image sphere_checker() {
    return make(16, 8, [](int i, int j) { return checker(i, j, kCheckLight, kCheckRed); });
}

fw::Image floor_checker() {
    return make(8, 8, [](int i, int j) { return checker(i, j, glm::vec3(0.9f), glm::vec3(0.1f)); });
}

fw::Image ramp() {
    return make(4, 4, [](int i, int j) {
        return glm::vec3((2.0f * float(i) + 1.0f) / 8.0f, (2.0f * float(j) + 1.0f) / 8.0f, 0.25f);
    });
}

fw::Image fine_checker() {
    return make(256, 256,
                [](int i, int j) { return checker(i, j, glm::vec3(1.0f), glm::vec3(0.0f)); });
}

fw::Image base_texture() {
    return make(8, 8, [](int i, int j) { return checker(i, j, kBaseLight, kBaseDark); });
}

fw::Image light_map() {
    return make(16, 16, [](int i, int j) {
        const glm::vec2 centre((float(i) + 0.5f) / 16.0f, (float(j) + 0.5f) / 16.0f);
        const float d = glm::distance(centre, glm::vec2(0.5f));
        return glm::vec3(std::max(0.15f, 1.0f - 1.5f * d));
    });
}

fw::Image load_image(const std::string& path) {
    int width = 0, height = 0, channels = 0;
    stbi_uc* data = stbi_load(path.c_str(), &width, &height, &channels, 4);
    if (!data) throw fw::Error("cannot read the image '" + path + "': " + stbi_failure_reason());
    const auto* rows = reinterpret_cast<const fw::Rgba8*>(data);
    fw::Image img(width, height);
    for (int j = 0; j < height; ++j) {
        // An image file stores its top row first; a texture's row 0 is its
        // bottom row, t = 0.
        // BEGIN SOLUTION
        // STUDENT: const int file_row = j;  // TODO: the file row that holds texture row j
        const int file_row = height - 1 - j;
        // END SOLUTION
        std::copy_n(rows + static_cast<std::size_t>(file_row) * width, width, &img.at(0, j));
    }
    stbi_image_free(data);
    return img;
}

}  // namespace texture_mapping
