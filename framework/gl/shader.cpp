#include "framework/gl/shader.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

#include "framework/error.hpp"
#include "framework/gl/debug.hpp"

namespace fw {

namespace {

struct StageInfo {
    Stage stage;
    const char* extension;
    const char* name;
    GLenum type;
};

constexpr StageInfo kStages[] = {
    {Stage::Vertex, ".vert", "vertex", GL_VERTEX_SHADER},
    {Stage::TessControl, ".tesc", "tessellation control", GL_TESS_CONTROL_SHADER},
    {Stage::TessEvaluation, ".tese", "tessellation evaluation", GL_TESS_EVALUATION_SHADER},
    {Stage::Geometry, ".geom", "geometry", GL_GEOMETRY_SHADER},
    {Stage::Fragment, ".frag", "fragment", GL_FRAGMENT_SHADER},
    {Stage::Compute, ".comp", "compute", GL_COMPUTE_SHADER},
};

const StageInfo& info(Stage stage) {
    for (const StageInfo& s : kStages)
        if (s.stage == stage) return s;
    return kStages[0];
}

bool ends_with(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(line);
    }
    return lines;
}

}  // namespace

GLenum gl_shader_type(Stage stage) { return info(stage).type; }
const char* stage_name(Stage stage) { return info(stage).name; }

Stage stage_from_path(const std::string& path) {
    std::string known;
    for (const StageInfo& s : kStages) {
        if (ends_with(path, s.extension)) return s.stage;
        known += std::string(known.empty() ? "" : ", ") + s.extension + " (" + s.name + ")";
    }
    throw UsageError("shader '" + path + "': unknown extension; the stage comes from the " +
                     "extension, one of " + known);
}

std::string shader_dir() {
    const char* env = std::getenv("LAB_SHADER_DIR");
    if (env && *env) return env;
    return LAB_SOURCE_DIR "/shaders";
}

std::string shader_path(const std::string& relative) {
    if (!relative.empty() && relative[0] == '/') return relative;
    return shader_dir() + "/" + relative;
}

std::string display_path(const std::string& path) {
    const std::string root = LAB_SOURCE_DIR "/";
    if (path.compare(0, root.size(), root) == 0) return path.substr(root.size());
    return path;
}

int log_line_number(const std::string& log_line) {
    // Mesa:   "0:12(5): error: ..."    (string 0, line 12, column 5)
    // NVIDIA: "0(12) : error C1008: ..."
    // Others: "ERROR: 0:12: ..."
    static const std::regex mesa(R"(^\s*\d+:(\d+)\(\d+\)\s*:)");
    static const std::regex nvidia(R"(^\s*\d+\((\d+)\)\s*:)");
    static const std::regex other(R"(^\s*(?:ERROR|WARNING):\s*\d+:(\d+):)");
    std::smatch m;
    if (std::regex_search(log_line, m, mesa) || std::regex_search(log_line, m, nvidia) ||
        std::regex_search(log_line, m, other))
        return std::atoi(m[1].str().c_str());
    return 0;
}

std::string format_compile_error(const std::string& path, Stage stage, const std::string& log,
                                 const std::string& source) {
    const std::vector<std::string> source_lines = split_lines(source);
    std::string body;
    int first_line = 0, last_quoted = 0;
    for (const std::string& line : split_lines(log)) {
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        body += "  " + line + "\n";
        int n = log_line_number(line);
        // Compilers often report several errors for one line; quote it once.
        if (n >= 1 && static_cast<std::size_t>(n) <= source_lines.size() && n != last_quoted) {
            if (first_line == 0) first_line = n;
            last_quoted = n;
            body += "  " + std::to_string(n) + " | " +
                    source_lines[static_cast<std::size_t>(n) - 1] + "\n";
        }
    }
    if (body.empty()) body = "  (the compiler gave no log)\n";
    std::string where = path + (first_line > 0 ? ":" + std::to_string(first_line) : "");
    return where + ": " + stage_name(stage) + " shader failed to compile:\n" + body;
}

Shader Shader::from_file(const std::string& path) {
    const Stage stage = stage_from_path(path);
    const std::string resolved = shader_path(path);
    std::ifstream in(resolved, std::ios::binary);
    std::ostringstream text;
    if (std::filesystem::is_regular_file(resolved) && in) text << in.rdbuf();
    if (!std::filesystem::is_regular_file(resolved) || !in || in.bad())
        throw Error("cannot read shader file '" + resolved + "'" +
                    (resolved == path ? std::string()
                                      : " ('" + path + "' in the shader directory " + shader_dir() +
                                            "; LAB_SHADER_DIR overrides it)"));
    Shader shader = from_source(stage, text.str(), display_path(resolved));
    shader.path_ = resolved;
    return shader;
}

Shader Shader::from_source(Stage stage, const std::string& source, const std::string& name) {
    Shader shader;
    shader.stage_ = stage;
    shader.path_ = name;
    shader.source_ = source;
    GLuint id = glCreateShader(gl_shader_type(stage));
    if (id == 0) throw Error("glCreateShader failed for " + name + " (is a GL context current?)");
    shader.handle_ = detail::Handle(id, [](GLuint n) { glDeleteShader(n); });
    const char* text = source.c_str();
    const auto length = static_cast<GLint>(source.size());
    glShaderSource(id, 1, &text, &length);
    glCompileShader(id);

    GLint ok = GL_FALSE, log_length = 0;
    glGetShaderiv(id, GL_COMPILE_STATUS, &ok);
    glGetShaderiv(id, GL_INFO_LOG_LENGTH, &log_length);
    std::string log(static_cast<std::size_t>(log_length > 0 ? log_length : 0), '\0');
    if (log_length > 0) glGetShaderInfoLog(id, log_length, nullptr, log.data());
    while (!log.empty() && log.back() == '\0') log.pop_back();
    if (ok != GL_TRUE) {
        // Mesa also reports the failure through KHR_debug; the exception
        // carries it, so the queued copy must not resurface at the next check.
        take_debug_messages();
        throw Error(format_compile_error(name, stage, log, source));
    }
    set_object_label(GL_SHADER, id, name);
    return shader;
}

}  // namespace fw
