#include "framework/text.hpp"

namespace fw {

std::string quoted_label(const std::string& label) {
    return label.empty() ? std::string("(unlabelled)") : "'" + label + "'";
}

std::string shell_quote(std::string_view s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string_view("'\\''") : std::string_view(&c, 1);
    return q + "'";
}

}  // namespace fw
