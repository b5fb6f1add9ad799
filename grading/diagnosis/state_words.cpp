#include "grading/diagnosis/state_words.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "framework/error.hpp"

namespace grading {

namespace {

using nlohmann::json;

const char* const kBoxParts[] = {"x", "y", "width", "height"};
const char* const kChannels[] = {"red", "green", "blue", "alpha"};

// GL's words for the fields whose path names them whole.
const std::map<std::string, std::string>& field_words() {
    static const std::map<std::string, std::string> kFields = {
        {"program", "the program in use (glUseProgram)"},
        {"blend.src_rgb", "glBlendFunc's source factor"},
        {"blend.dst_rgb", "glBlendFunc's destination factor"},
        {"blend.src_alpha", "glBlendFuncSeparate's source alpha factor"},
        {"blend.dst_alpha", "glBlendFuncSeparate's destination alpha factor"},
        {"blend.equation_rgb", "glBlendEquation's mode"},
        {"blend.equation_alpha", "glBlendEquationSeparate's alpha mode"},
        {"blend.color", "glBlendColor's colour"},
        {"depth.func", "glDepthFunc's function"},
        {"depth.mask", "glDepthMask's flag"},
        {"depth.range", "glDepthRange's near and far"},
        {"stencil.func", "glStencilFunc's function"},
        {"stencil.ref", "glStencilFunc's reference value"},
        {"stencil.value_mask", "glStencilFunc's mask"},
        {"stencil.fail", "glStencilOp's sfail (stencil test fails)"},
        {"stencil.zfail", "glStencilOp's dpfail (depth test fails)"},
        {"stencil.zpass", "glStencilOp's dppass (both pass)"},
        {"stencil.write_mask", "glStencilMask's mask"},
        {"cull.face", "glCullFace's mode"},
        {"cull.front_face", "glFrontFace's mode"},
        {"polygon_mode", "glPolygonMode's mode"},
        {"line_width", "glLineWidth's width"},
        {"point_size", "glPointSize's size"},
        {"patch_vertices", "glPatchParameteri's GL_PATCH_VERTICES"},
        {"clear_color", "glClearColor's colour"},
        {"clear_depth", "glClearDepth's depth"},
        {"clear_stencil", "glClearStencil's value"},
        {"depth_mask", "glDepthMask's flag"},
        {"stencil_write_mask", "glStencilMask's mask"},
        {"read_buffer", "glReadBuffer's mode"},
        {"pack_alignment", "glPixelStorei's GL_PACK_ALIGNMENT"},
        {"pack_buffer", "the buffer bound to GL_PIXEL_PACK_BUFFER"},
        {"barriers", "the barriers (glMemoryBarrier) issued since the last dispatch"},
        {"vertex_array.label", "the vertex array (glBindVertexArray)"},
        {"vertex_array.elements",
         "the element buffer (GL_ELEMENT_ARRAY_BUFFER of the vertex array)"},
        {"transform_feedback.paused", "transform feedback's pause (glPauseTransformFeedback)"}};
    return kFields;
}

// The path's part `i`, or "" past its end.
std::string part(const std::vector<std::string>& path, size_t i) {
    return i < path.size() ? path[i] : std::string();
}

// "textures.UNIT[.FIELD]": a texture unit that a sampler reads, or a field of it.
std::string texture_words(const std::vector<std::string>& path) {
    const std::string unit = "the texture on unit " + part(path, 1);
    const std::string f = part(path, 2);
    if (f == "texture") return unit + " (glActiveTexture, glBindTexture)";
    if (f == "levels") return "the mipmap levels of " + unit + " (glGenerateMipmap)";
    if (f.empty()) return "texture unit " + part(path, 1) + " (read by a sampler uniform)";
    std::string param = "GL_TEXTURE_" + f;
    std::transform(param.begin(), param.end(), param.begin(), ::toupper);
    return param + " (glTexParameteri) of " + unit;
}

// "vertex_array.attributes.LOCATION[.FIELD]": an attribute or a field of it.
std::string attribute_words(const std::vector<std::string>& path) {
    const std::string attr = "attribute " + part(path, 2);
    const std::string f = part(path, 3);
    if (f == "enabled") return "glEnableVertexAttribArray for " + attr;
    if (f == "divisor") return "glVertexAttribDivisor's divisor for " + attr;
    if (f == "buffer") return "the buffer of " + attr + " (bound when glVertexAttribPointer ran)";
    if (f == "current") return "the current value of " + attr + " (glVertexAttrib*)";
    if (f.empty()) return attr;
    return "glVertexAttribPointer's " + f + " for " + attr;
}

std::string joined(const std::vector<std::string>& path) {
    std::string out;
    for (const std::string& p : path) out += (out.empty() ? "" : ".") + p;
    return out;
}

// The words of a path that no field's entry names, by its first part; "" where
// the handler does not know the rest of the path.
using Path = std::vector<std::string>;
using PathWords = std::string (*)(const Path& path, const std::string& call);

std::string box_words(const Path& path, const char* function) {
    if (path.size() != 2) return "";
    return std::string(function) + "'s " + kBoxParts[std::stoi(path[1]) & 3];
}

std::string block_words(const Path& path, const char* target) {
    return "the buffer of block " + part(path, 1) + " (glBindBufferBase(" + target + ", ...))" +
           (path.size() > 2 ? "'s " + part(path, 2) : "");
}

const std::map<std::string, PathWords>& path_words() {
    static const std::map<std::string, PathWords> kHeads = {
        {"args", [](const Path& p, const std::string& call) { return call + "'s " + part(p, 1); }},
        {"viewport", [](const Path& p, const std::string&) { return box_words(p, "glViewport"); }},
        {"scissor", [](const Path& p, const std::string&) { return box_words(p, "glScissor"); }},
        {"color_mask",
         [](const Path& p, const std::string&) {
             return p.size() == 2 ? "glColorMask's " + std::string(kChannels[std::stoi(p[1]) & 3])
                                  : std::string();
         }},
        {"uniforms",
         [](const Path& p, const std::string&) {
             return "uniform " + part(p, 1) + (p.size() > 2 ? "[" + part(p, 2) + "]" : "");
         }},
        {"textures", [](const Path& p, const std::string&) { return texture_words(p); }},
        {"vertex_array",
         [](const Path& p, const std::string&) {
             return part(p, 1) == "attributes" ? attribute_words(p) : std::string();
         }},
        {"framebuffer",
         [](const Path& p, const std::string&) {
             return "the draw framebuffer" + (p.size() > 1 ? "'s " + part(p, 1) : "") +
                    " (glBindFramebuffer)";
         }},
        {"uniform_buffers",
         [](const Path& p, const std::string&) { return block_words(p, "GL_UNIFORM_BUFFER"); }},
        {"storage_buffers",
         [](const Path& p, const std::string&) {
             return block_words(p, "GL_SHADER_STORAGE_BUFFER");
         }},
        {"transform_feedback",
         [](const Path&, const std::string&) {
             return std::string(
                 "the transform feedback buffers (glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, "
                 "...))");
         }},
        {"buffer",
         [](const Path&, const std::string&) { return std::string("the buffer it reads"); }},
        {"images",
         [](const Path& p, const std::string&) {
             return "image unit " + part(p, 1) + " (glBindImageTexture)";
         }},
    };
    return kHeads;
}

}  // namespace

std::string gl_words(const std::vector<std::string>& path, const std::string& call) {
    const std::map<std::string, std::string>& kFields = field_words();
    const std::string whole = joined(path);
    if (whole.rfind("stencil_back.", 0) == 0) {
        auto it = kFields.find("stencil." + path[1]);
        if (it != kFields.end()) return it->second + " for back faces (glStencil*Separate)";
    }
    auto it = kFields.find(whole);
    if (it != kFields.end()) return it->second;
    const auto head = path_words().find(path[0]);
    if (head == path_words().end()) return whole;
    const std::string words = head->second(path, call);
    return words.empty() ? whole : words;
}

json read_state_words(const std::string& root, const std::string& lab_dir,
                      const fw::CheckpointFile& file) {
    const std::string rel = "labs/" + lab_dir + "/grading/state_words.json";
    const std::filesystem::path path = std::filesystem::path(root) / rel;
    if (!std::filesystem::exists(path)) return nullptr;
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    const json words = json::parse(text.str(), nullptr, /*allow_exceptions=*/false,
                                   /*ignore_comments=*/true);
    if (words.is_discarded()) throw fw::UsageError(rel + ": not valid JSON");
    if (!words.is_object() || words.value("version", 0) != 1 || !words.contains("words") ||
        !words["words"].is_array())
        throw fw::UsageError(rel + ": expected {\"version\": 1, \"words\": [...]}");
    std::set<std::string> params;
    for (const fw::Checkpoint& cp : file.checkpoints)
        for (const auto& [name, value] : cp.params.items()) params.insert(name);
    for (size_t i = 0; i < words["words"].size(); ++i) {
        const json& w = words["words"][i];
        const std::string where = rel + ", entry " + std::to_string(i + 1);
        for (const char* name : {"field", "text"})
            if (!w.is_object() || !w.contains(name) || !w[name].is_string() ||
                w[name].get_ref<const std::string&>().empty())
                throw fw::UsageError(where + ": needs a non-empty string \"" + name + "\"");
        if (!w.contains("when")) continue;
        if (!w["when"].is_object())
            throw fw::UsageError(where + ": \"when\" must be an object of parameters");
        for (const auto& [name, value] : w["when"].items())
            if (!params.count(name))
                throw fw::UsageError(where + ": \"when\" names " + name +
                                     ", which no checkpoint of the lab sets");
    }
    return words;
}

std::string sheet_words(const json& words, const std::vector<std::string>& path,
                        const fw::Checkpoint& cp) {
    if (!words.is_object() || !words.contains("words") || !words["words"].is_array()) return "";
    const std::string whole = joined(path);
    std::string best;
    size_t best_field = 0, best_when = 0;
    for (const json& w : words["words"]) {
        const std::string field = w.value("field", "");
        if (field.empty() || (whole != field && whole.rfind(field + ".", 0) != 0)) continue;
        const json when = w.value("when", json::object());
        bool all = true;
        for (const auto& [k, v] : when.items())
            all = all && cp.params.is_object() && cp.params.contains(k) && cp.params[k] == v;
        if (!all) continue;
        if (field.size() > best_field || (field.size() == best_field && when.size() >= best_when)) {
            best = w.value("text", "");
            best_field = field.size();
            best_when = when.size();
        }
    }
    return best;
}

}  // namespace grading
