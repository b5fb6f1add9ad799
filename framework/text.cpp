#include "framework/text.hpp"

#include <cstdio>

namespace fw {

std::string number_text(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

std::string trimmed_decimals(double v, int decimals) {
    char buf[384];  // %f of the largest double has 309 digits before the point
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    std::string s = buf;
    if (s.find('.') != std::string::npos) {
        s.erase(s.find_last_not_of('0') + 1);
        if (s.back() == '.') s.pop_back();
    }
    return s == "-0" ? "0" : s;
}

std::string quoted_label(const std::string& label) {
    return label.empty() ? std::string("(unlabelled)") : "'" + label + "'";
}

std::string shell_quote(std::string_view s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string_view("'\\''") : std::string_view(&c, 1);
    return q + "'";
}

}  // namespace fw
