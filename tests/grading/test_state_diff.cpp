// grading/diagnosis/state_diff: records made on a real context, a reference and
// a planted state mistake of labs 7-10, and the sentence that names it: the
// draw, the call and its argument, the student's value, the sheet's words,
// and the reference's value only for a hidden checkpoint. What cannot change
// a draw's result (the order of state calls, an equivalent call, a uniform
// optimised out) is never named; draws in another order are said to be.
#include <glad/gl.h>

#include <filesystem>

#include "grading/diagnosis/state_diff.hpp"
#include "grading/diagnosis/state_words.hpp"
#include "grading/judge/checks.hpp"
#include "tests/framework/record_scene.hpp"
#include "tests/support/test_support.hpp"

using nlohmann::json;
using record_test::Scene;

namespace {

fw::Checkpoint checkpoint(json params, const std::string& visibility = "visible") {
    fw::Checkpoint cp;
    cp.name = "planted";
    cp.visibility = visibility;
    cp.params = std::move(params);
    return cp;
}

// A word of the sheet for every field the cases below plant a mistake in.
const json kWords = json::parse(R"({"version": 1, "words": [
  {"field": "blend.dst_rgb", "when": {"mode": "over"}, "text": "the sheet's over weights what is behind by 1 - alpha"},
  {"field": "blend", "text": "the sheet's blend table"},
  {"field": "order", "when": {"scene": "sorting"}, "text": "the sheet sorts back to front"}]})");

std::string diff(const json& student, const json& reference, const fw::Checkpoint& cp) {
    return grading::state_difference(student, reference, cp, kWords, cp.visibility == "visible");
}

}  // namespace

TEST_CASE(
    "state diff: a wrong blend factor is named at its draw and argument, with the sheet's words") {
    Scene scene;
    const auto blended = [&](GLenum dst) {
        return scene.record([&, dst] {
            scene.draw();  // the background, blending off
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, dst);
            scene.draw();
        });
    };
    const json reference = blended(GL_ONE_MINUS_SRC_ALPHA), student = blended(GL_DST_ALPHA);
    const json params = {{"scene", "blend"}, {"mode", "over"}};
    CHECK(diff(student, reference, checkpoint(params)) ==
          "Draw 2 of scene `blend`: glBlendFunc's destination factor is GL_DST_ALPHA; the "
          "sheet's over weights what is behind by 1 - alpha.");
    // A hidden checkpoint's (and staff's) report shows the reference's value too.
    CHECK(diff(student, reference, checkpoint(params, "hidden")) ==
          "Draw 2 of scene `blend`: glBlendFunc's destination factor is GL_DST_ALPHA; the "
          "reference's is GL_ONE_MINUS_SRC_ALPHA; the sheet's over weights what is behind by 1 - "
          "alpha.");
    // Without the sheet's words for it: GL's terms alone (here the field's
    // less specific entry; with no words file, none).
    CHECK(diff(student, reference, checkpoint({{"scene", "blend"}, {"mode", "additive"}})) ==
          "Draw 2 of scene `blend`: glBlendFunc's destination factor is GL_DST_ALPHA; the sheet's "
          "blend table.");
    CHECK(grading::state_difference(student, reference, checkpoint(params), json(), true) ==
          "Draw 2 of scene `blend`: glBlendFunc's destination factor is GL_DST_ALPHA.");
    CHECK(diff(reference, reference, checkpoint(params)).empty());
}

TEST_CASE(
    "state diff: lab 7's depth mask, stencil function and scissor, lab 8's wrap and filter, "
    "lab 10's clip distance") {
    Scene scene;
    struct Planted {
        const char* what;
        std::function<void()> reference, student;
        std::string names;
    };
    const std::vector<Planted> planted = {
        {"depth writes left on", [] { glEnable(GL_DEPTH_TEST), glDepthMask(GL_FALSE); },
         [] { glEnable(GL_DEPTH_TEST), glDepthMask(GL_TRUE); },
         "Draw 1 of scene `x`: glDepthMask's flag is GL_TRUE."},
        {"stencil function swapped",
         [] { glEnable(GL_STENCIL_TEST), glStencilFunc(GL_EQUAL, 1, 0xFF); },
         [] { glEnable(GL_STENCIL_TEST), glStencilFunc(GL_NOTEQUAL, 1, 0xFF); },
         "Draw 1 of scene `x`: glStencilFunc's function is GL_NOTEQUAL."},
        {"scissor not scaled to the viewport",
         [] { glViewport(0, 0, 128, 128), glEnable(GL_SCISSOR_TEST), glScissor(0, 32, 64, 64); },
         [] { glViewport(0, 0, 128, 128), glEnable(GL_SCISSOR_TEST), glScissor(0, 16, 32, 32); },
         "Draw 1 of scene `x`: glScissor's y is 16."},
        {"wrap t left repeating",
         [] { glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE); }, [] {},
         "Draw 1 of scene `x`: GL_TEXTURE_WRAP_T (glTexParameteri) of the texture on unit 0 is "
         "GL_REPEAT."},
        {"nearest for linear", [] {},
         [] { glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST); },
         "Draw 1 of scene `x`: GL_TEXTURE_MIN_FILTER (glTexParameteri) of the texture on unit 0 "
         "is GL_NEAREST."},
        {"compare mode left off",
         [] {
             glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
             glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
         },
         [] { glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL); },
         "Draw 1 of scene `x`: GL_TEXTURE_COMPARE_MODE (glTexParameteri) of the texture on unit 0 "
         "is GL_NONE, so the texture is read without a comparison."},
        {"clip distance not enabled", [] { glEnable(GL_CLIP_DISTANCE0); }, [] {},
         "Draw 1 of scene `x`: GL_CLIP_DISTANCE0 is not enabled (glEnable)."}};
    for (const Planted& p : planted) {
        CAPTURE(p.what);
        const json reference = scene.record([&] {
            glBindTexture(GL_TEXTURE_2D, scene.texture);
            p.reference();
            scene.draw();
        });
        const json student = scene.record([&] {
            glBindTexture(GL_TEXTURE_2D, scene.texture);
            p.student();
            scene.draw();
        });
        CHECK(diff(student, reference, checkpoint({{"scene", "x"}})) == p.names);
    }
}

TEST_CASE("state diff: what cannot change a result is never named") {
    Scene scene;
    const json reference = scene.record([&] {
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthFunc(GL_LESS);
        scene.draw();
    });
    const json student = scene.record([&] {
        // Another order of the state calls, the separate form with equal
        // factors, a depth function with the test off, a uniform the
        // compiler dropped.
        glDepthFunc(GL_GREATER);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA,
                            GL_ONE_MINUS_SRC_ALPHA);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        scene.program.set_if_active("u_unused", 2.0f);
        scene.draw();
    });
    CHECK(diff(student, reference, checkpoint({{"scene", "blend"}, {"mode", "over"}})).empty());
}

TEST_CASE("state diff: the same draws in another order are a sort's mistake") {
    Scene scene;
    const glm::vec4 colours[] = {{1, 0, 0, 0.5f}, {0, 1, 0, 0.5f}, {0, 0, 1, 0.5f}};
    const auto in_order = [&](std::vector<int> order) {
        return scene.record([&] {
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            for (int i : order) {
                scene.program.set("u_color", colours[i]);
                scene.draw();
            }
        });
    };
    const json reference = in_order({2, 1, 0}), student = in_order({0, 1, 2});
    CHECK(diff(student, reference, checkpoint({{"scene", "sorting"}})) ==
          "Draw 1 of scene `sorting`: the draws come in another order: your Draw 1 is the "
          "reference's Draw 3 (the same state), drawn earlier than there; the sheet sorts back to "
          "front.");
    // A draw of another colour is not an order.
    const json other = scene.record([&] {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        for (int i : {0, 1, 1}) {
            scene.program.set("u_color", colours[i]);
            scene.draw();
        }
    });
    CHECK(diff(other, reference, checkpoint({{"scene", "sorting"}})).find("another order") ==
          std::string::npos);
}

// What another driver would record for the same draws: the scene's program
// with the attribute and the uniform that Mesa drops kept active (a linker
// may keep either; Mesa 25 keeps an attribute that feeds an unused output,
// Mesa 22 drops it), and an array uniform whose last element it drops.
namespace {
json kept_active(json record, const json& weights) {
    for (json& event : record["events"]) {
        if (!event.contains("program")) continue;
        event["vertex_array"]["attributes"]["1"] = {
            {"name", "a_unused"}, {"enabled", false}, {"current", {0, 0, 0, 1}}};
        event["uniforms"]["u_unused"] = 0;
        event["uniforms"]["u_weights"] = weights;
    }
    return record;
}
}  // namespace

TEST_CASE("state diff: what one driver keeps active and another drops is never a difference") {
    Scene scene;
    const auto blended = [&](GLenum dst) {
        return scene.record([&, dst] {
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, dst);
            scene.draw();
            scene.draw();
        });
    };
    const json four = {0.1, 0.2, 0.3, 0.4}, three = {0.1, 0.2, 0.3};
    const json reference = kept_active(blended(GL_ONE_MINUS_SRC_ALPHA), three);
    const json params = {{"scene", "blend"}, {"mode", "over"}};
    // The solution on the other driver: nothing to name.
    CHECK(diff(blended(GL_ONE_MINUS_SRC_ALPHA), reference, checkpoint(params)).empty());
    CHECK(diff(kept_active(blended(GL_ONE_MINUS_SRC_ALPHA), four), reference, checkpoint(params))
              .empty());
    // A mistake is named as on one driver, not as the attribute the other keeps.
    CHECK(diff(blended(GL_DST_ALPHA), reference, checkpoint(params)) ==
          "Draw 1 of scene `blend`: glBlendFunc's destination factor is GL_DST_ALPHA; the "
          "sheet's over weights what is behind by 1 - alpha.");
    // An element both keep still counts.
    CHECK(diff(kept_active(blended(GL_ONE_MINUS_SRC_ALPHA), json{0.1, 0.2, 0.9, 0.4}), reference,
               checkpoint(params))
              .find("u_weights") != std::string::npos);
}

TEST_CASE("state diff: another order is named across drivers") {
    Scene scene;
    const glm::vec4 colours[] = {{1, 0, 0, 0.5f}, {0, 1, 0, 0.5f}};
    const auto in_order = [&](std::vector<int> order) {
        return scene.record([&] {
            for (int i : order) {
                scene.program.set("u_color", colours[i]);
                scene.draw();
            }
        });
    };
    const json reference = kept_active(in_order({1, 0}), json{1.0, 2.0});
    CHECK(diff(in_order({0, 1}), reference, checkpoint({{"scene", "sorting"}}))
              .find("the draws come in another order") != std::string::npos);
}

// The staff's files the state diff reads are checked before any grading: a
// sheet's words that are not what state_words.hpp says, and a reference
// record that is not a record, each an error naming the file and the fix.
TEST_CASE("state diff: a malformed state_words.json or reference record is an error naming it") {
    namespace fs = std::filesystem;
    const fs::path root = fs::path(fw::test::out_dir()) / "staff";
    const fs::path lab_dir = root / "labs" / "07_framebuffer_ops";
    fs::create_directories(lab_dir / "grading");
    fs::create_directories(lab_dir / "reference");
    grading::LabData lab;
    lab.id = "framebuffer-ops";
    lab.dir = "07_framebuffer_ops";
    lab.root = root.string();
    lab.file.checkpoints.push_back(checkpoint({{"scene", "blend"}, {"mode", "over"}}));
    auto words_error = [&](const std::string& text) {
        fw::test::write_text((lab_dir / "grading" / "state_words.json").string(), text);
        return fw::test::thrown([&] { grading::read_state_words(lab.root, lab.dir, lab.file); });
    };
    fw::test::check_mentions(words_error("{"), {"grading/state_words.json", "not valid JSON"});
    fw::test::check_mentions(words_error(R"({"version": 1, "words": {}})"),
                             {"state_words.json", "\"words\""});
    fw::test::check_mentions(words_error(R"({"version": 1, "words": [{"field": "blend"}]})"),
                             {"entry 1", "\"text\""});
    fw::test::check_mentions(words_error(R"({"version": 1, "words": [{"field": "blend", "text": "t",
                         "when": {"moed": "over"}}]})"),
                             {"entry 1", "moed", "no checkpoint"});
    fw::test::write_text((lab_dir / "grading" / "state_words.json").string(),
                         R"({"version": 1, "words": [{"field": "blend", "text": "t",
                              "when": {"mode": "over"}}]})");
    CHECK_NOTHROW(grading::read_state_words(lab.root, lab.dir, lab.file));
    fs::remove(lab_dir / "grading" / "state_words.json");
    CHECK(grading::read_state_words(lab.root, lab.dir, lab.file).is_null());

    const fs::path record = lab_dir / "reference" / "planted.record.json";
    fw::test::write_text(record.string(), "<<<<<<< HEAD\n");
    fw::test::check_mentions(fw::test::thrown([&] { grading::check_reference_records(lab); }),
                             {"reference/planted.record.json", "course bless framebuffer-ops"});
    fw::test::write_text(record.string(), R"({"version": 1, "events": []})");
    CHECK_NOTHROW(grading::check_reference_records(lab));
}
