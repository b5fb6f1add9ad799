#include "framework/window/panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <glm/gtc/type_ptr.hpp>

#include "framework/window/keys.hpp"

namespace fw::win {

namespace {

// ImGui formats slider values with printf, so a '%' in a unit must be doubled.
std::string slider_format(const char* number, const std::string& unit) {
    std::string fmt = number;
    if (!unit.empty()) fmt += " ";
    for (char c : unit) fmt += (c == '%') ? std::string("%%") : std::string(1, c);
    return fmt;
}

void tooltip(const Param& p) {
    if (!ImGui::IsItemHovered()) return;
    ImGui::BeginTooltip();
    if (!p.help_text.empty()) ImGui::TextUnformatted(p.help_text.c_str());
    std::string facts = p.name + ": " + p.range_text() + ", default " + p.default_text();
    ImGui::TextDisabled("%s", facts.c_str());
    ImGui::EndTooltip();
}

bool enum_combo(const char* label, const std::vector<std::string>& choices, int& index) {
    bool changed = false;
    if (ImGui::BeginCombo(label, choices[static_cast<size_t>(index)].c_str())) {
        for (int i = 0; i < static_cast<int>(choices.size()); ++i) {
            if (ImGui::Selectable(choices[static_cast<size_t>(i)].c_str(), i == index)) {
                index = i;
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

// True when the user changed the value.
bool param_widget(const Param& p, ParamValues& values) {
    std::string label = p.name;
    if (p.shortcut != 0)
        label += "  [" + std::string(1, static_cast<char>(std::toupper(p.shortcut))) + "]";
    // AlwaysClamp: Ctrl+click lets the user type a value; keep it in range.
    const ImGuiSliderFlags clamp = ImGuiSliderFlags_AlwaysClamp;
    bool changed = false;
    switch (p.type) {
        case ParamType::Float: {
            double lo = p.min, hi = p.max;
            // A positive range over several decades (near = 0.0001 .. 10) is
            // only usable on a logarithmic slider, with significant digits.
            const bool decades = lo > 0.0 && hi / lo >= 1000.0;
            const ImGuiSliderFlags flags = clamp | (decades ? ImGuiSliderFlags_Logarithmic : 0);
            changed =
                ImGui::SliderScalar(label.c_str(), ImGuiDataType_Double, &values.number_ref(p.name),
                                    &lo, &hi, slider_format("%.4g", p.unit_text).c_str(), flags);
            break;
        }
        case ParamType::Int: {
            double& value = values.number_ref(p.name);
            int i = static_cast<int>(std::lround(value));
            changed = ImGui::SliderInt(label.c_str(), &i, static_cast<int>(p.min),
                                       static_cast<int>(p.max),
                                       slider_format("%d", p.unit_text).c_str(), clamp);
            if (changed) value = i;
            break;
        }
        case ParamType::Bool:
            changed = ImGui::Checkbox(label.c_str(), &values.flag_ref(p.name));
            break;
        case ParamType::Enum:
            changed = enum_combo(label.c_str(), p.choices, values.choice_ref(p.name));
            break;
        case ParamType::Color:
            changed = ImGui::ColorEdit3(label.c_str(), glm::value_ptr(values.color_ref(p.name)));
            break;
    }
    tooltip(p);
    return changed;
}

void shortcut_table(const LabInfo& info) {
    if (!ImGui::CollapsingHeader("All keys and controls")) return;
    if (ImGui::BeginTable("keys", 2)) {
        for (const Shortcut& s : shortcut_list(info)) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(s.keys.c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(s.action.c_str());
        }
        ImGui::EndTable();
    }
    for (const std::string& line : info.controls) ImGui::BulletText("%s", line.c_str());
}

}  // namespace

bool draw_panel(const RegisteredLab& lab, ParamValues& params, const std::string& gl_renderer,
                const std::string& notice) {
    const LabInfo& info = lab.info;
    char name[128];
    std::snprintf(name, sizeof name, "lab %02d %s", info.number, info.id.c_str());
    const ImGuiViewport* view = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(view->WorkPos.x + 8, view->WorkPos.y + 8),
                            ImGuiCond_FirstUseEver);
    // Taller than the window: scroll rather than hang off the bottom.
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(FLT_MAX, view->WorkSize.y - 16));
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin(name, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::TextUnformatted(info.title.c_str());
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::TextDisabled("%.0f fps (%.1f ms), %s", static_cast<double>(io.Framerate),
                        io.Framerate > 0.0f ? 1000.0 / static_cast<double>(io.Framerate) : 0.0,
                        gl_renderer.c_str());
    if (!notice.empty()) {
        // The panel sizes itself to what it holds: unwrapped, this line would
        // make it as wide as the whole text.
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 330.0f);
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "%s", notice.c_str());
        ImGui::PopTextWrapPos();
    }
    ImGui::Separator();

    ImGui::PushItemWidth(150);
    bool changed = false;
    for (const Param& p : info.params) changed = param_widget(p, params) || changed;
    ImGui::PopItemWidth();
    if (ImGui::Button("Reset to defaults")) {
        params = default_params(lab);
        changed = true;
    }

    ImGui::Separator();
    ImGui::TextUnformatted("R reload shaders   F12 screenshot   Esc quit");
    shortcut_table(info);
    ImGui::End();
    return changed;
}

void draw_errors(const std::vector<std::string>& messages) {
    if (messages.empty()) return;
    const ImGuiViewport* view = ImGui::GetMainViewport();
    const float margin = 8.0f;
    float width = std::min(view->WorkSize.x - 2 * margin, 760.0f);
    ImGui::SetNextWindowPos(ImVec2(view->WorkPos.x + view->WorkSize.x * 0.5f,
                                   view->WorkPos.y + view->WorkSize.y - margin),
                            ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    // Height 0: fit the text; the window scrolls if it is taller than the view.
    ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f),
                                        ImVec2(width, view->WorkSize.y - 2 * margin));
    ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.45f, 0.02f, 0.02f, 0.95f));
    ImGui::PushStyleColor(ImGuiCol_TitleBg, ImVec4(0.75f, 0.05f, 0.05f, 1.0f));
    ImGui::PushStyleColor(ImGuiCol_TitleBgActive, ImVec4(0.75f, 0.05f, 0.05f, 1.0f));
    ImGui::Begin("Errors", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
    for (size_t i = 0; i < messages.size(); ++i) {
        if (i > 0) ImGui::Separator();
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(messages[i].c_str());
        ImGui::PopTextWrapPos();
    }
    ImGui::End();
    ImGui::PopStyleColor(3);
}

}  // namespace fw::win
