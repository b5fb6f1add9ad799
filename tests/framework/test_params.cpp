// Parameter declarations and values, without a GL context: parsing, ranges,
// error messages, JSON, and checkpoint files.
#include <filesystem>
#include <fstream>

#include "framework/checkpoints.hpp"
#include "framework/error.hpp"
#include "framework/lab.hpp"
#include "framework/params.hpp"
#include "framework/text.hpp"
#include "tests/support/test_support.hpp"

namespace {

enum class Scene { Cards, ZFight };
constexpr fw::Choice<Scene> kScenes[] = {{Scene::Cards, "cards"}, {Scene::ZFight, "zfight"}};
enum class Other { Cards, ZFight };

const std::vector<fw::Param>& sample_params() {
    static const std::vector<fw::Param> params = {
        fw::Param::number("fov", 60).range(10, 150).unit("deg").help("field of view").key('F'),
        fw::Param::integer("subdiv", 2).range(0, 5),
        fw::Param::boolean("wireframe", true),
        fw::Param::choice("scene", kScenes, Scene::Cards),
        fw::Param::color("tint", "ff8000"),
    };
    return params;
}

template <class F>
std::string error_of(F&& f) {
    return fw::test::thrown<fw::UsageError>(f);
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("numbers are written one way in every message") {
    CHECK(fw::number_text(0.5) == "0.5");
    CHECK(fw::number_text(1.0 / 3.0) == "0.333333");
    CHECK(fw::number_text(1.0 / 3.0, 7) == "0.3333333");
    CHECK(fw::number_text(1e-5) == "1e-05");
    CHECK(fw::trimmed_decimals(2.5, 2) == "2.5");
    CHECK(fw::trimmed_decimals(3.0, 2) == "3");
    CHECK(fw::trimmed_decimals(0.125, 2) == "0.12");
    CHECK(fw::trimmed_decimals(-0.001, 2) == "0");
    CHECK(fw::trimmed_decimals(1200.0, 0) == "1200");
}

enum class Mode { A, B };
constexpr fw::Choice<Mode> kModes[] = {{Mode::A, "a"}, {Mode::B, "b"}};

TEST_CASE("typed handles name a parameter once and read it as its type") {
    constexpr fw::ParamId<float> kFov{"fov"};
    constexpr fw::ParamId<int> kCount{"count"};
    constexpr fw::ParamId<bool> kOn{"on"};
    constexpr fw::ParamId<glm::vec3> kTint{"tint"};
    constexpr fw::ParamId<Mode> kMode{"mode"};
    const std::vector<fw::Param> params = {
        fw::Param::number(kFov, 60).range(10, 150), fw::Param::integer(kCount, 3).range(0, 9),
        fw::Param::boolean(kOn, true), fw::Param::color(kTint, "ff0000"),
        fw::Param::choice(kMode, kModes, Mode::B)};
    fw::ParamValues p("demo", &params);
    CHECK(p[kFov] == 60.0f);
    CHECK(p[kCount] == 3);
    CHECK(p[kOn]);
    CHECK(p[kTint] == glm::vec3(1, 0, 0));
    CHECK(p[kMode] == Mode::B);
    p.set("mode", "a");
    p.set("count", "7");
    CHECK(p[kMode] == Mode::A);
    CHECK(p[kCount] == 7);
    CHECK(p.set_clamped(kFov, 500) == 150);
    CHECK(p[kFov] == 150.0f);
    // A handle whose name the lab does not declare fails as the name would.
    constexpr fw::ParamId<float> kMissing{"missing"};
    fw::test::check_mentions(fw::test::thrown([&] { (void)p[kMissing]; }), {"missing"});
}

TEST_CASE("defaults come from the declaration") {
    fw::ParamValues v("demo", &sample_params());
    CHECK(v.number("fov") == 60.0f);
    CHECK(v.integer("subdiv") == 2);
    CHECK(v.flag("wireframe"));
    CHECK(v.get<Scene>("scene") == Scene::Cards);
    CHECK(v.text("scene") == "cards");
    CHECK(v.color("tint").r == doctest::Approx(1.0));
    CHECK(v.color("tint").g == doctest::Approx(128.0 / 255.0));
    CHECK(v.text("tint") == "ff8000");
}

TEST_CASE("set parses every type") {
    fw::ParamValues v("demo", &sample_params());
    v.set_assignment("fov=45.5");
    v.set("subdiv", "5");
    v.set("wireframe", "off");
    v.set("scene", "zfight");
    v.set("tint", "#00ff00");
    CHECK(v.number("fov") == 45.5f);
    CHECK(v.integer("subdiv") == 5);
    CHECK_FALSE(v.flag("wireframe"));
    CHECK(v.get<Scene>("scene") == Scene::ZFight);
    CHECK(v.color("tint") == glm::vec3(0, 1, 0));
    auto j = v.to_json();
    CHECK(j["fov"] == 45.5);
    CHECK(j["subdiv"] == 5);
    CHECK(j["wireframe"] == false);
    CHECK(j["scene"] == "zfight");
    CHECK(j["tint"] == "00ff00");
}

TEST_CASE("bad values name the lab, the parameter and what is valid") {
    fw::ParamValues v("demo", &sample_params());
    std::string e = error_of([&] { v.set("fov", "200"); });
    CHECK(contains(e, "lab 'demo', parameter 'fov'"));
    CHECK(contains(e, "out of range"));
    CHECK(contains(e, "[10, 150] deg"));
    CHECK(contains(error_of([&] { v.set("fov", "wide"); }), "'wide' is not a number"));
    CHECK(contains(error_of([&] { v.set("fov", "nan"); }), "is not a number"));
    CHECK(contains(error_of([&] { v.set("subdiv", "2.5"); }), "not an integer"));
    CHECK(contains(error_of([&] { v.set("scene", "teapot"); }), "valid values: cards, zfight"));
    CHECK(contains(error_of([&] { v.set("tint", "orange"); }), "hex rrggbb"));
    CHECK(contains(error_of([&] { v.set("nope", "1"); }),
                   "its parameters are: fov, subdiv, wireframe, scene, tint"));
    CHECK(contains(error_of([&] { v.set_assignment("fov"); }), "name=value"));
    // A failed set leaves the previous value.
    CHECK(v.number("fov") == 60.0f);
}

TEST_CASE("reading a parameter as the wrong type is a programming error") {
    fw::ParamValues v("demo", &sample_params());
    CHECK_THROWS_AS(v.flag("fov"), fw::Error);
    CHECK_THROWS_AS(v.get<Scene>("wireframe"), fw::Error);
    CHECK(v.number("subdiv") == 2.0f);  // an int reads as a number
    // A choice reads only as the enum it is bound to; the message names both.
    const std::string e = fw::test::thrown([&] { v.get<Other>("scene"); });
    CHECK(contains(e, "parameter 'scene' is a choice of"));
    CHECK(contains(e, "Scene"));
    CHECK(contains(e, "Other"));
}

TEST_CASE("set_clamped keeps a number inside its declared range") {
    fw::ParamValues v("demo", &sample_params());
    CHECK(v.set_clamped("fov", 500) == 150.0);
    CHECK(v.number("fov") == 150.0f);
    CHECK(v.set_clamped("fov", -3) == 10.0);
    CHECK(v.set_clamped("fov", 42.5) == 42.5);
    CHECK(v.set_clamped("subdiv", 3.4) == 3.0);  // an integer stays whole
    CHECK(v.set_clamped("subdiv", 99) == 5.0);
    CHECK_THROWS_AS(v.set_clamped("scene", 1), fw::Error);
}

TEST_CASE("a declaration whose default is outside its range or choices is refused") {
    CHECK_THROWS_AS(fw::Param::number("x", 5).range(0, 1), fw::Error);
    CHECK_THROWS_AS(fw::Param::color("x", "12345"), fw::Error);
}

TEST_CASE("a choice declaration is checked when it is made") {
    enum class Abc { A, B, C };
    using C = fw::Choice<Abc>;
    const auto default_missing = [] {
        fw::Param::choice("x", {C{Abc::A, "a"}, {Abc::B, "b"}}, Abc::C);
    };
    const std::string missing = fw::test::thrown(default_missing);
    CHECK(contains(missing, "parameter 'x'"));
    CHECK(contains(missing, "not one of its choices {a, b}"));
    const auto name_twice = [] { fw::Param::choice("x", {C{Abc::A, "a"}, {Abc::B, "a"}}, Abc::A); };
    CHECK(contains(fw::test::thrown(name_twice), "the name 'a' is given twice"));
    const auto value_twice = [] {
        fw::Param::choice("x", {C{Abc::A, "a"}, {Abc::A, "b"}}, Abc::A);
    };
    CHECK(contains(fw::test::thrown(value_twice), "'a' and 'b' are the same enum value"));
    const fw::Param ok = fw::Param::choice("x", {C{Abc::C, "c"}, {Abc::A, "a"}}, Abc::A);
    CHECK(ok.default_text() == "a");
    CHECK(ok.range_text() == "{c, a}");
}

TEST_CASE("a lab that sets its own number, id or dir is refused at registration") {
    fw::LabInfo info;
    info.id = "demo";
    const std::string e =
        fw::test::thrown([&] { fw::register_lab("98_demo", info, [] { return nullptr; }); });
    CHECK(contains(e, "lab folder '98_demo'"));
    CHECK(contains(e, "come from the folder's name"));
    CHECK_THROWS_AS(fw::find_lab("demo"), fw::UsageError);  // nothing was registered
}

TEST_CASE("a lab's number and id come from its folder's name") {
    int number = -1;
    std::string id;
    fw::parse_lab_dir("02_robot_arm", number, id);
    CHECK(number == 2);
    CHECK(id == "robot-arm");
    fw::parse_lab_dir("17_x", number, id);
    CHECK(number == 17);
    CHECK(id == "x");
    for (const char* bad : {"robot_arm", "2_robot", "02-robot", "02_", "02_Robot", "02_a b"}) {
        INFO(std::string(bad));
        CHECK(contains(fw::test::thrown([&] { fw::parse_lab_dir(bad, number, id); }), "NN_"));
    }
}

TEST_CASE("animate is the framework's bool: declared or not, and refused as another type") {
    const std::vector<fw::Param> with = {fw::Param::boolean(fw::kAnimate, false)};
    fw::ParamValues p("demo", &with);
    CHECK(p.declares(fw::kAnimate));
    CHECK(!p[fw::kAnimate]);
    p.set("animate", "true");
    CHECK(p[fw::kAnimate]);
    CHECK(!fw::ParamValues("demo", &sample_params()).declares(fw::kAnimate));

    // A lab that declares `animate` as a number does not start.
    fw::LabInfo info;
    info.params = {fw::Param::number("animate", 1)};
    REQUIRE(fw::register_lab("97_animated", info, [] { return nullptr; }));
    fw::test::check_mentions(
        fw::test::thrown([] { fw::default_params(fw::find_lab("animated")); }),
        {"lab 'animated'", "parameter 'animate'", "fw::kAnimate", "Param::boolean"});
}

TEST_CASE("keyboard steps") {
    CHECK(sample_params()[0].key_step() == doctest::Approx(7.0));  // (150 - 10) / 20
    CHECK(sample_params()[1].key_step() == 1.0);
}

TEST_CASE("checkpoint files are validated against the declaration") {
    fw::RegisteredLab lab{{99, "demo", "99_demo", "Demo", sample_params(), {}, {}}, nullptr};
    std::string dir = fw::test::out_dir();
    auto write = [&](const std::string& text) {
        std::ofstream(dir + "/cp.json") << text;
        return dir + "/cp.json";
    };
    auto good = fw::load_checkpoints(lab, write(R"({
        // comments are allowed
        "lab": "demo",
        "checkpoints": [
          {"name": "a", "params": {"fov": 30, "scene": "zfight", "wireframe": false}},
          {"name": "b", "visibility": "hidden", "checks": [{"kind": "image"}]}
        ]})"));
    REQUIRE(good.size() == 2);
    CHECK(good[1].visibility == "hidden");
    fw::ParamValues a = fw::checkpoint_params(lab, good[0]);
    CHECK(a.number("fov") == 30.0f);
    CHECK(a.get<Scene>("scene") == Scene::ZFight);
    CHECK(a.integer("subdiv") == 2);

    auto error_for = [&](const std::string& text) {
        try {
            fw::load_checkpoints(lab, write(text));
        } catch (const fw::Error& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    CHECK(contains(
        error_for(R"({"lab": "demo", "checkpoints": [{"name": "a", "params": {"fov": 1}}]})"),
        "checkpoint 'a'"));
    CHECK(contains(
        error_for(R"({"lab": "demo", "checkpoints": [{"name": "a", "params": {"zoom": 1}}]})"),
        "no parameter 'zoom'"));
    CHECK(contains(error_for(R"({"lab": "demo", "checkpoints": [{"name": "a"}, {"name": "a"}]})"),
                   "used twice"));
    CHECK(contains(
        error_for(R"({"lab": "demo", "checkpoints": [{"name": "a", "visibility": "secret"}]})"),
        "visibility"));
    CHECK(contains(error_for(R"({"lab": "demo", "checkpoints": [{"name": "a", "param": {}}]})"),
                   "unknown field \"param\""));
    CHECK(contains(error_for(R"({"lab": "demo", "checkpoints": [{"name": "a b"}]})"),
                   "letters, digits"));
    CHECK(contains(error_for(R"({"lab": "other", "checkpoints": []})"), "belongs to lab 'demo'"));
    CHECK(contains(error_for(R"({"checkpoints": []})"), "not in a lab folder"));
    CHECK(contains(error_for(R"({"checkpoints": [)"), dir + "/cp.json"));
    CHECK(contains(error_for(R"({"checkpoints": [)"), "not valid JSON"));
    CHECK_THROWS_WITH_AS(fw::load_checkpoints(lab, dir + "/missing.json"),
                         doctest::Contains("missing.json"), fw::Error);
}

TEST_CASE("a checkpoints file in a lab folder belongs to that folder's lab") {
    const std::string dir = fw::test::out_dir() + "/labs/99_demo";
    std::filesystem::create_directories(dir);
    const std::string path = dir + "/checkpoints.json";
    std::ofstream(path) << R"({"checkpoints": [{"name": "a"}]})";
    CHECK(fw::read_checkpoint_file(path).lab == "demo");
    std::ofstream(path) << R"({"lab": "demo", "checkpoints": []})";
    CHECK(fw::read_checkpoint_file(path).lab == "demo");
    std::ofstream(path) << R"({"lab": "pipeline", "checkpoints": []})";
    const std::string e = fw::test::thrown([&] { fw::read_checkpoint_file(path); });
    CHECK(contains(e, "is in folder 99_demo, lab 'demo'"));
    CHECK(contains(e, "remove \"lab\""));
}
