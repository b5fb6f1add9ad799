// The WebSocket messages of `lab serve`'s page (docs/contract.md, `lab
// serve`), each a JSON object with its "type", applied to the live lab.
#include "framework/serve/messages.hpp"

#include <string_view>

#include "framework/error.hpp"

namespace fw {

namespace {

using nlohmann::json;

std::string text_of(const json& value) {
    if (value.is_string()) return value.get<std::string>();
    if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
    if (value.is_number()) return value.dump();
    throw UsageError("a value must be a string, a number or true/false, not " + value.dump());
}

double number_field(const json& m, const char* name) {
    if (!m.contains(name) || !m[name].is_number())
        throw UsageError(std::string("\"") + name + "\" must be a number");
    return m[name].get<double>();
}

std::string string_field(const json& m, const char* name) {
    if (!m.contains(name) || !m[name].is_string())
        throw UsageError(std::string("\"") + name + "\" must be a string");
    return m[name].get<std::string>();
}

std::uint64_t set_value(LiveLab& live, ClientFlags&, const json& m) {
    if (!m.contains("value")) throw UsageError("\"value\" is missing");
    return live.set(string_field(m, "name"), text_of(m["value"]));
}

std::uint64_t load_checkpoint(LiveLab& live, ClientFlags&, const json& m) {
    return live.load_checkpoint(string_field(m, "name"));
}

std::uint64_t drag(LiveLab& live, ClientFlags&, const json& m) {
    const double dx = number_field(m, "dx");
    return live.drag(dx, number_field(m, "dy"));
}

std::uint64_t scroll(LiveLab& live, ClientFlags&, const json& m) {
    return live.scroll(number_field(m, "steps"));
}

std::uint64_t key(LiveLab& live, ClientFlags&, const json& m) {
    return live.key(string_field(m, "key"), m.value("shift", false));
}

std::uint64_t reload(LiveLab& live, ClientFlags&, const json&) { return live.reload_shaders(); }

std::uint64_t resize(LiveLab& live, ClientFlags&, const json& m) {
    const double w = number_field(m, "width"), h = number_field(m, "height");
    if (w != static_cast<int>(w) || h != static_cast<int>(h))
        throw UsageError("\"width\" and \"height\" must be whole numbers");
    return live.resize(static_cast<int>(w), static_cast<int>(h));
}

std::uint64_t play(LiveLab& live, ClientFlags& client, const json& m) {
    if (!m.contains("on") || !m["on"].is_boolean())
        throw UsageError("\"on\" must be true or false");
    const bool on = m["on"].get<bool>();
    if (client.playing.exchange(on) == on) return live.latest() ? live.latest()->version : 0;
    return live.play(on);
}

std::uint64_t set_format(LiveLab& live, ClientFlags& client, const json& m) {
    const std::string format = string_field(m, "format");
    if (format != "jpeg" && format != "png")
        throw UsageError("\"format\" must be \"jpeg\" or \"png\", not \"" + format + "\"");
    client.png = format == "png";
    return live.redraw();  // the frame now on screen, again, in that format
}

// The page's messages, by "type"; each returns the version its change will
// show in.
struct MessageType {
    std::string_view type;
    std::uint64_t (*apply)(LiveLab&, ClientFlags&, const json&);
};
const MessageType kMessageTypes[] = {{"set", set_value},    {"checkpoint", load_checkpoint},
                                     {"drag", drag},        {"scroll", scroll},
                                     {"key", key},          {"reload", reload},
                                     {"size", resize},      {"play", play},
                                     {"format", set_format}};

}  // namespace

std::uint64_t apply_message(LiveLab& live, ClientFlags& client, const json& m) {
    const std::string type = string_field(m, "type");
    for (const MessageType& t : kMessageTypes)
        if (t.type == type) return t.apply(live, client, m);
    std::string types;
    for (const MessageType& t : kMessageTypes)
        types += (types.empty() ? "" : ", ") + std::string(t.type);
    throw UsageError("unknown message type \"" + type + "\"; types: " + types);
}

}  // namespace fw
