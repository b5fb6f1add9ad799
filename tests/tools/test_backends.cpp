// The two offscreen backends render every checkpoint of every lab within the
// fuzzy threshold of each other, and byte for byte alike when the same
// renderer is behind both (docs/contract.md, Checks, `image`), and `lab
// render-checkpoints` writes the PNG, PFM and stats of each.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/test_support.hpp"

namespace {

// Renders all checkpoints on `backend`; false (with the reason logged) when
// the backend is missing on this machine.
bool render_all(const std::string& backend, const std::string& dir, std::string& why) {
    std::filesystem::remove_all(dir);
    auto r = fw::test::run_command(fw::test::bin_dir() + "/lab render-checkpoints --backend " +
                                   backend + " --out " + dir);
    MESSAGE("render-checkpoints --backend " << backend << ": exit " << r.exit_code << "\n"
                                            << r.output);
    if (r.exit_code == 3) {
        why = r.output;
        return false;
    }
    REQUIRE(r.exit_code == 0);
    return true;
}

}  // namespace

TEST_CASE("osmesa and egl agree on every checkpoint") {
    std::string out = fw::test::out_dir();
    fw::test::remove_when_passed(out);
    std::string why;
    // Without OSMesa there is nothing to compare: this whole test is that
    // backend's own case. EGL alone is covered by every other test.
    for (const std::string backend : {"osmesa", "egl"}) {
        if (render_all(backend, out + "/" + backend, why)) continue;
        fw::test::skip_part_without(backend, "comparing the backends, which needs both", why);
        if (fw::test::backend_required(backend)) return;  // failed above
        std::exit(77);
    }
    int compared = 0, identical = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(out + "/osmesa")) {
        if (entry.path().extension() != ".png") continue;
        std::string rel = std::filesystem::relative(entry.path(), out + "/osmesa").string();
        CAPTURE(rel);
        fw::Image a = fw::read_png(entry.path().string());
        fw::Image b = fw::read_png(out + "/egl/" + rel);
        fw::CompareResult c = fw::compare_images(a, b);
        MESSAGE(rel << ": " << c.summary());
        CHECK(c.passed);
        // The same renderer behind both (llvmpipe, say) must give the same
        // bytes, which is why a reference may be blessed on either backend;
        // different renderers (a GPU behind EGL) need only pass the image check.
        const std::string stem = rel.substr(0, rel.size() - 4);
        const auto stats_a =
            nlohmann::json::parse(std::ifstream(out + "/osmesa/" + stem + ".json"));
        const auto stats_b = nlohmann::json::parse(std::ifstream(out + "/egl/" + stem + ".json"));
        const bool same_renderer = stats_a["gl_renderer"] == stats_b["gl_renderer"];
        if (same_renderer) {
            CHECK(a.pixels == b.pixels);
            ++identical;
        }

        std::string pfm = entry.path().string();
        pfm.replace(pfm.size() - 4, 4, ".pfm");
        fw::DepthImage da = fw::read_pfm(pfm);
        fw::DepthImage db = fw::read_pfm(out + "/egl/" + stem + ".pfm");
        REQUIRE(da.values.size() == db.values.size());
        float worst = 0.0f;
        for (size_t i = 0; i < da.values.size(); ++i)
            worst = std::max(worst, std::fabs(da.values[i] - db.values[i]));
        MESSAGE(rel << ": largest depth difference " << worst);
        CHECK(worst <= (same_renderer ? 0.0f : 1e-5f));

        CHECK(stats_a["backend"] == "osmesa");
        CHECK(stats_b["backend"] == "egl");
        CHECK(stats_a["width"] == 512);
        ++compared;
    }
    MESSAGE(compared << " checkpoints compared, " << identical
                     << " of them required to be identical (the same renderer on both)");
    CHECK(compared >= 6);
}
