// The registry of buffer references and their known mistakes (buffer_reference.hpp).
#include "grading/units/buffer_reference.hpp"

#include <algorithm>
#include <map>

#include "framework/error.hpp"
#include "framework/lab.hpp"
#include "framework/text.hpp"

namespace grading {

namespace {

// Keyed by lab, then reference name; maps so that messages list names in
// order, with transparent comparison so that lookups take string views.
using ByName = std::map<std::string, BufferReference, std::less<>>;
std::map<std::string, ByName, std::less<>>& references() {
    static std::map<std::string, ByName, std::less<>> all;
    return all;
}
// Every mistake, in registration order (a reference may register after its
// mistakes: files initialise in any order).
std::vector<BufferMistake>& mistakes() {
    static std::vector<BufferMistake> all;
    return all;
}

bool starts_with_word(const std::string& text, const std::string& word) {
    return text == word || text.rfind(word + " ", 0) == 0;
}

bool ends_with(const std::string& text, const std::string& end) {
    return text.size() >= end.size() &&
           text.compare(text.size() - end.size(), end.size(), end) == 0;
}

}  // namespace

bool register_buffer_reference(std::string_view lab_dir, BufferReference reference) {
    int number = 0;
    fw::parse_lab_dir(lab_dir, number, reference.lab);
    const std::string where = "buffer reference '" + reference.lab + "." + reference.name + "'";
    if (!reference.function) throw fw::Error(where + " has no function");
    if (reference.element.empty())
        throw fw::Error(where + " needs the noun of one element, e.g. \"particle\"");
    if (!starts_with_word(reference.verb, "is") && !starts_with_word(reference.verb, "has"))
        throw fw::Error(where + ": its verb \"" + reference.verb +
                        "\" must start with \"is\" or \"has\" (\"is at\"), so that the report "
                        "can say what it should be");
    ByName& lab = references()[reference.lab];
    if (lab.count(reference.name)) throw fw::Error(where + " is registered twice");
    const std::string name = reference.name;
    lab[name] = std::move(reference);
    return true;
}

bool register_buffer_mistake(std::string_view lab_dir, BufferMistake mistake) {
    int number = 0;
    fw::parse_lab_dir(lab_dir, number, mistake.lab);
    const std::string where = "buffer mistake '" + mistake.id + "' of reference '" + mistake.lab +
                              "." + mistake.reference + "'";
    const bool id_ok =
        !mistake.id.empty() && std::all_of(mistake.id.begin(), mistake.id.end(), [](char c) {
            return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
        });
    if (!id_ok) throw fw::Error(where + ": its ID must be lower-case letters, digits and '-'");
    if (!mistake.function) throw fw::Error(where + " has no function");
    if (mistake.sentence.empty()) throw fw::Error(where + " needs a sentence");
    for (const BufferMistake& m : mistakes())
        if (m.lab == mistake.lab && m.reference == mistake.reference && m.id == mistake.id)
            throw fw::Error(where + " is registered twice");
    mistakes().push_back(std::move(mistake));
    return true;
}

const BufferReference& find_buffer_reference(std::string_view lab, std::string_view name) {
    auto& all = references();
    const auto l = all.find(lab);
    const std::string names =
        l == all.end() ? std::string()
                       : fw::join(l->second, ", ", [](const auto& entry) { return entry.first; });
    for (const BufferMistake& m : mistakes())
        if (m.lab == lab && (l == all.end() || !l->second.count(m.reference)))
            throw fw::Error("buffer mistake '" + m.id + "' names the reference '" + m.reference +
                            "', which lab '" + m.lab + "' does not register; " +
                            (names.empty() ? "it registers none" : "it registers: " + names));
    if (l != all.end()) {
        const auto f = l->second.find(name);
        if (f != l->second.end()) return f->second;
    }
    throw fw::Error("course has no buffer reference '" + std::string(name) + "' for lab '" +
                    std::string(lab) + "'; " +
                    (names.empty() ? "it has none for that lab" : "it has: " + names) +
                    " (COURSE_BUFFER_REFERENCE in labs/NN_name/grading/*.cpp)");
}

std::vector<const BufferMistake*> buffer_mistakes(std::string_view lab,
                                                  std::string_view reference) {
    std::vector<const BufferMistake*> out;
    for (const BufferMistake& m : mistakes())
        if (m.lab == lab && m.reference == reference) out.push_back(&m);
    return out;
}

std::string plural_noun(const std::string& noun) {
    if (ends_with(noun, "ex")) return noun.substr(0, noun.size() - 2) + "ices";
    if (ends_with(noun, "s") || ends_with(noun, "x") || ends_with(noun, "ch") ||
        ends_with(noun, "sh"))
        return noun + "es";
    if (noun.size() > 1 && noun.back() == 'y' &&
        std::string("aeiou").find(noun[noun.size() - 2]) == std::string::npos)
        return noun.substr(0, noun.size() - 1) + "ies";
    return noun + "s";
}

std::string expected_verb(const std::string& verb) {
    if (starts_with_word(verb, "is")) return "should be" + verb.substr(2);
    if (starts_with_word(verb, "has")) return "should have" + verb.substr(3);
    return "should be";
}

}  // namespace grading
