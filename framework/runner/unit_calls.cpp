// units.json of `lab grade-child` (unit_calls.hpp).
#include "framework/runner/unit_calls.hpp"

#include <exception>

#include "framework/error.hpp"
#include "framework/json_glm.hpp"

namespace fw {

using json = nlohmann::json;

namespace {

// The lab's unit function `name`; null when it has none.
const UnitFunction* find_unit(const RegisteredLab& lab, const std::string& name) {
    for (const UnitFunction& f : lab.info.functions)
        if (f.name == name) return &f;
    return nullptr;
}

}  // namespace

// units.json: every unit call of the job, by id, with its result or the
// error it threw. The job gives the calls of one function together
// ({"function", "first", "args": [...]}: call k's id is "u" and first + k),
// so that a lab's thousands of cases cost the job an argument list each;
// the results are written call by call, not built as one object first. An
// id given twice is written twice, and a JSON reader keeps the last.
std::string units_text(const RegisteredLab& lab, const json& groups) {
    std::string text = "{";
    for (const json& group : groups) {
        const std::string name = group.value("function", "");
        const UnitFunction* f = find_unit(lab, name);
        const long first = group.value("first", 0L);
        const auto args = group.find("args");
        if (args == group.end() || !args->is_array()) continue;
        for (size_t k = 0; k < args->size(); ++k) {
            if (text.size() > 1) text += ',';
            text += "\"u" + std::to_string(first + static_cast<long>(k)) + "\":";
            const size_t entry = text.size();
            try {
                if (!f)
                    throw Error("lab '" + lab.info.id + "' has no unit function '" + name + "'");
                const json result = f->call((*args)[k]);
                text += "{\"result\":";
                append_json(text, result);
                text += '}';
            } catch (const std::exception& e) {
                text.resize(entry);  // a result cut short by a string it cannot write
                text += "{\"error\":" +
                        json(e.what()).dump(-1, ' ', false, json::error_handler_t::replace) + "}";
            }
        }
    }
    return text + "}\n";
}

}  // namespace fw
