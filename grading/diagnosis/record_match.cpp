#include "grading/diagnosis/record_match.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace grading {

namespace {

using nlohmann::json;

// The event's maps keyed by an item of the program's interface: an
// attribute's location, a uniform's or block's name, a sampler's or image's
// unit. The path from the event to the map.
const std::vector<std::vector<const char*>> kInterfaceMaps = {{"vertex_array", "attributes"},
                                                              {"uniforms"},
                                                              {"textures"},
                                                              {"images"},
                                                              {"uniform_buffers"},
                                                              {"storage_buffers"}};

// Fields the record leaves out when the program has none of their items.
bool omitted_when_empty(const std::vector<const char*>& path) {
    return path.size() == 1 && std::string(path[0]) != "uniforms";
}

json* map_at(json& event, const std::vector<const char*>& path) {
    json* v = &event;
    for (const char* p : path) {
        if (!v->is_object() || !v->contains(p)) return nullptr;
        v = &(*v)[p];
    }
    return v->is_object() ? v : nullptr;
}

// What one record holds active, program by program: each interface map's
// keys, and each array uniform's shortest length.
struct Interface {
    std::vector<std::set<std::string>> keys =
        std::vector<std::set<std::string>>(kInterfaceMaps.size());
    std::map<std::string, size_t> lengths;
};

bool is_array_uniform(const json& value) { return value.is_array() && !value.empty(); }

std::map<std::string, Interface> interfaces(json& record) {
    std::map<std::string, Interface> out;
    for (json& event : record["events"]) {
        if (!event.is_object() || !event.contains("program") || !event["program"].is_string())
            continue;
        Interface& in = out[event["program"].get<std::string>()];
        for (size_t m = 0; m < kInterfaceMaps.size(); ++m)
            if (json* map = map_at(event, kInterfaceMaps[m]))
                for (const auto& [key, value] : map->items()) {
                    in.keys[m].insert(key);
                    if (m == 1 && is_array_uniform(value)) {
                        auto [it, fresh] = in.lengths.emplace(key, value.size());
                        if (!fresh) it->second = std::min(it->second, value.size());
                    }
                }
    }
    return out;
}

// Keeps in `record` only what `common` holds, program by program.
void narrow(json& record, const std::map<std::string, Interface>& common) {
    for (json& event : record["events"]) {
        if (!event.is_object() || !event.contains("program") || !event["program"].is_string())
            continue;
        const auto found = common.find(event["program"].get<std::string>());
        if (found == common.end()) continue;
        const Interface& in = found->second;
        for (size_t m = 0; m < kInterfaceMaps.size(); ++m) {
            json* map = map_at(event, kInterfaceMaps[m]);
            if (!map) continue;
            for (auto it = map->begin(); it != map->end();)
                it = in.keys[m].count(it.key()) ? std::next(it) : map->erase(it);
            if (m == 1)
                for (auto& [name, value] : map->items()) {
                    const auto length = in.lengths.find(name);
                    if (length != in.lengths.end() && value.is_array() &&
                        value.size() > length->second)
                        value.erase(value.begin() + static_cast<std::ptrdiff_t>(length->second),
                                    value.end());
                }
            if (map->empty() && omitted_when_empty(kInterfaceMaps[m]))
                event.erase(kInterfaceMaps[m][0]);
        }
    }
}

}  // namespace

void keep_common_interface(json& student, json& reference) {
    std::map<std::string, Interface> s = interfaces(student), r = interfaces(reference), common;
    for (const auto& [program, mine] : s) {
        const auto theirs = r.find(program);
        if (theirs == r.end()) continue;
        Interface both;
        for (size_t m = 0; m < kInterfaceMaps.size(); ++m)
            std::set_intersection(mine.keys[m].begin(), mine.keys[m].end(),
                                  theirs->second.keys[m].begin(), theirs->second.keys[m].end(),
                                  std::inserter(both.keys[m], both.keys[m].end()));
        for (const auto& [name, length] : mine.lengths) {
            const auto other = theirs->second.lengths.find(name);
            if (other != theirs->second.lengths.end())
                both.lengths[name] = std::min(length, other->second);
        }
        common[program] = std::move(both);
    }
    narrow(student, common);
    narrow(reference, common);
}

}  // namespace grading
