#include "framework/window/keys.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cctype>
#include <cstdlib>
#include <sstream>

#include "framework/error.hpp"
#include "framework/session.hpp"

namespace fw::win {

std::vector<Shortcut> shortcut_list(const LabInfo& info) {
    std::vector<Shortcut> list = LabSession::shortcuts(info);
    list.push_back({"F12", "save screenshot-" + info.id + "-NNN.png"});
    list.push_back({"Esc", "quit"});
    return list;
}

std::vector<ScriptedKey> parse_key_script(const std::string& script) {
    std::vector<ScriptedKey> keys;
    std::stringstream items(script);
    std::string item;
    while (std::getline(items, item, ',')) {
        auto bad = [&] {
            throw UsageError("LAB_RUN_SCRIPT: '" + item +
                             "' is not FRAME:KEY (KEY: a letter, a digit, Shift+KEY, F12 or Esc), "
                             "e.g. LAB_RUN_SCRIPT=1:D,2:F12");
        };
        size_t colon = item.find(':');
        if (colon == std::string::npos || colon == 0) bad();
        char* end = nullptr;
        long frame = std::strtol(item.c_str(), &end, 10);
        if (end != item.c_str() + colon || frame < 1) bad();
        ScriptedKey k;
        k.frame = static_cast<int>(frame);
        std::string name = item.substr(colon + 1);
        if (name.rfind("Shift+", 0) == 0) {
            k.mods = GLFW_MOD_SHIFT;
            name = name.substr(6);
        }
        if (name == "F12")
            k.key = GLFW_KEY_F12;
        else if (name == "Esc")
            k.key = GLFW_KEY_ESCAPE;
        else if (name.size() == 1 && std::isalnum(static_cast<unsigned char>(name[0])))
            k.key = std::toupper(static_cast<unsigned char>(name[0]));
        else
            bad();
        keys.push_back(k);
    }
    return keys;
}

}  // namespace fw::win
