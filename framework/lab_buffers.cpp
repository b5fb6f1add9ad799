// Writing and reading the buffers file (lab_buffers.hpp).
#include "framework/lab_buffers.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "framework/error.hpp"
#include "framework/json_glm.hpp"

namespace fw {

namespace {

using nlohmann::json;

// A name as a message quotes it: what a child wrote may be of any length.
std::string shown(const std::string& name) {
    return "'" + (name.size() > 80 ? name.substr(0, 80) + "..." : name) + "'";
}

// The fewest digits that read back as the same float.
void append_float(std::string& out, float v) {
    if (!std::isfinite(v)) {
        out += '"';
        out += non_finite_name(v);
        out += '"';
        return;
    }
    char text[32];
    const auto written = std::to_chars(text, text + sizeof text, v);
    out.append(text, written.ptr);
}

LabBuffer parse_one(const std::string& name, const json& entry, const std::string& file) {
    const std::string where = file + ": buffer " + shown(name);
    if (name.empty()) throw Error(file + ": a buffer has an empty name");
    if (!entry.is_object())
        throw Error(where + " must be an object {\"components\": N, \"values\": [...]}");
    for (const auto& [field, value] : entry.items()) {
        (void)value;
        if (field != "components" && field != "values")
            throw Error(where + " has the unknown field " + shown(field) +
                        "; its fields are components and values");
    }
    LabBuffer b;
    b.name = name;
    const json* components = entry.contains("components") ? &entry["components"] : nullptr;
    if (!components || !components->is_number_integer() || components->get<long long>() < 1 ||
        components->get<long long>() > kMaxBufferComponents)
        throw Error(
            where + ": \"components\" must be an integer from 1 to " +
            std::to_string(kMaxBufferComponents) +
            (components ? ", got " + components->dump().substr(0, 40) : ", and is missing"));
    b.components = components->get<int>();
    if (!entry.contains("values") || !entry["values"].is_array())
        throw Error(where + ": \"values\" must be an array of numbers");
    const json& values = entry["values"];
    b.values.reserve(values.size());
    for (size_t i = 0; i < values.size(); ++i) {
        const std::optional<double> v = json_number(values[i]);
        if (!v)
            throw Error(where + ": \"values\"[" + std::to_string(i) + "] is " +
                        values[i].dump().substr(0, 40) +
                        ", not a number (nor \"NaN\", \"Infinity\", \"-Infinity\")");
        b.values.push_back(static_cast<float>(*v));
    }
    return b;
}

}  // namespace

void check_lab_buffers(const std::vector<LabBuffer>& buffers, const std::string& lab) {
    std::set<std::string> names;
    for (const LabBuffer& b : buffers) {
        const std::string where = "lab '" + lab + "': buffers(): LabBuffer " + shown(b.name);
        if (b.name.empty()) throw Error("lab '" + lab + "': buffers(): a LabBuffer has no name");
        if (!names.insert(b.name).second)
            throw Error(where + " is returned twice; each buffer needs a name of its own");
        if (b.components < 1 || b.components > kMaxBufferComponents)
            throw Error(where + ": components is " + std::to_string(b.components) +
                        "; it must be 1 to " + std::to_string(kMaxBufferComponents) +
                        " (floats per element)");
    }
}

std::string buffers_json(const std::vector<LabBuffer>& buffers) {
    std::string out = "{";
    for (size_t k = 0; k < buffers.size(); ++k) {
        const LabBuffer& b = buffers[k];
        out += (k ? ",\n" : "") + json(b.name).dump() +
               ": {\"components\": " + std::to_string(b.components) + ", \"values\": [";
        for (size_t i = 0; i < b.values.size(); ++i) {
            if (i) out += ',';
            append_float(out, b.values[i]);
        }
        out += "]}";
    }
    return out + "}\n";
}

void write_buffers(const std::string& path, const std::vector<LabBuffer>& buffers) {
    std::ofstream out(path, std::ios::binary);
    if (!(out << buffers_json(buffers)))
        throw Error("cannot write '" + path + "'; check that its directory exists and is writable");
}

std::vector<LabBuffer> parse_buffers(const std::string& text, const std::string& file) {
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::exception& e) {
        throw Error(file + " is not valid JSON: " + e.what());
    }
    if (!doc.is_object())
        throw Error(file +
                    " must be a JSON object of buffers by name, e.g. {\"particles\": "
                    "{\"components\": 3, \"values\": [...]}}");
    std::vector<LabBuffer> out;
    for (const auto& [name, entry] : doc.items()) out.push_back(parse_one(name, entry, file));
    return out;
}

}  // namespace fw
