#include "framework/gl/shader.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <vector>

#include "framework/error.hpp"
#include "framework/gl/debug.hpp"
#include "framework/text.hpp"

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

// Included file k is numbered from line k * kIncludedLineBase + 1, and is
// source string k: compilers that report source strings (NVIDIA) name k,
// and those that report string 0 for all (Mesa) still give a line that
// tells the file. A shader file longer than this is not expected.
constexpr int kIncludedLineBase = 100000;

bool ends_with(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// set_shader_overrides: by the path a program names, the text compiled instead.
std::map<std::string, std::string>& overrides() {
    static std::map<std::string, std::string> texts;
    return texts;
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
    for (const StageInfo& s : kStages)
        if (ends_with(path, s.extension)) return s.stage;
    const auto described = [](const StageInfo& s) {
        return std::string(s.extension) + " (" + s.name + ")";
    };
    throw UsageError("shader '" + path + "': unknown extension; the stage comes from the " +
                     "extension, one of " + join(kStages, ", ", described));
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

void set_shader_overrides(std::map<std::string, std::string> texts) {
    overrides() = std::move(texts);
}

std::string display_path(const std::string& path) {
    const std::string root = LAB_SOURCE_DIR "/";
    if (path.compare(0, root.size(), root) == 0) return path.substr(root.size());
    return path;
}

int log_line_number(const std::string& log_line, int* source_string) {
    // Mesa:   "0:12(5): error: ..."    (string 0, line 12, column 5)
    // NVIDIA: "0(12) : error C1008: ..."
    // Others: "ERROR: 0:12: ..."
    static const std::regex mesa(R"(^\s*(\d+):(\d+)\(\d+\)\s*:)");
    static const std::regex nvidia(R"(^\s*(\d+)\((\d+)\)\s*:)");
    static const std::regex other(R"(^\s*(?:ERROR|WARNING):\s*(\d+):(\d+):)");
    std::smatch m;
    if (std::regex_search(log_line, m, mesa) || std::regex_search(log_line, m, nvidia) ||
        std::regex_search(log_line, m, other)) {
        if (source_string) *source_string = std::atoi(m[1].str().c_str());
        return std::atoi(m[2].str().c_str());
    }
    if (source_string) *source_string = 0;
    return 0;
}

std::string format_compile_error(const std::string& path, Stage stage, const std::string& log,
                                 const std::string& source,
                                 const std::vector<IncludedFile>& included) {
    std::vector<std::vector<std::string>> files{split_lines(source)};
    std::vector<std::string> paths{path};
    for (const IncludedFile& f : included) {
        files.push_back(split_lines(f.text));
        paths.push_back(f.path);
    }
    std::string body, where;
    std::pair<int, int> last_quoted{-1, 0};
    for (const std::string& line : split_lines(log)) {
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        body += "  " + line + "\n";
        int string_number = 0;
        int n = log_line_number(line, &string_number);
        // Mesa reports every line as source string 0: included file k
        // starts at line k * kIncludedLineBase + 1 (expand_includes).
        if (n > kIncludedLineBase) {
            string_number = n / kIncludedLineBase;
            n %= kIncludedLineBase;
        }
        if (string_number < 0 || static_cast<std::size_t>(string_number) >= files.size()) continue;
        const auto file = static_cast<std::size_t>(string_number);
        // Compilers often report several errors for one line; quote it once.
        if (n >= 1 && static_cast<std::size_t>(n) <= files[file].size() &&
            std::pair(string_number, n) != last_quoted) {
            if (where.empty()) where = paths[file] + ":" + std::to_string(n);
            last_quoted = {string_number, n};
            body += "  " + (file > 0 ? paths[file] + ":" : std::string()) + std::to_string(n) +
                    " | " + files[file][static_cast<std::size_t>(n) - 1] + "\n";
        }
    }
    if (body.empty()) body = "  (the compiler gave no log)\n";
    if (where.empty()) where = path;
    return where + ": " + stage_name(stage) + " shader failed to compile:\n" + body;
}

std::string expand_includes(const std::string& text, const std::string& path,
                            std::vector<IncludedFile>& included) {
    static const std::regex include(R"re(^\s*#\s*include\s*"([^"/]+)"\s*$)re");
    static const std::regex any_include(R"(^\s*#\s*include\b)");
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    std::string out;
    int number = 0;
    for (const std::string& line : split_lines(text)) {
        ++number;
        std::smatch m;
        if (!std::regex_search(line, any_include)) {
            out += line + "\n";
            continue;
        }
        const std::string where = display_path(path) + ":" + std::to_string(number) + ": ";
        if (!std::regex_search(line, m, include))
            throw ShaderError(
                display_path(path),
                where + "expected #include \"name\" naming a file in the same folder: " + line);
        const std::string file = (folder / m[1].str()).string();
        std::ifstream in(file, std::ios::binary);
        std::ostringstream content;
        if (!std::filesystem::is_regular_file(file) || !(content << in.rdbuf()))
            throw ShaderError(display_path(path),
                              where + "cannot read included file '" + file + "'");
        for (const std::string& inner : split_lines(content.str()))
            if (std::regex_search(inner, any_include))
                throw ShaderError(
                    display_path(file),
                    display_path(file) + ": an included file may not include another");
        included.push_back({display_path(file), content.str()});
        const std::size_t k = included.size();
        out += "#line " + std::to_string(k * kIncludedLineBase + 1) + " " + std::to_string(k) +
               "\n" + content.str() + "\n#line " + std::to_string(number + 1) + " 0\n";
    }
    return out;
}

Shader Shader::from_file(const std::string& path) {
    const Stage stage = stage_from_path(path);
    const std::string resolved = shader_path(path);
    std::string text;
    // A text in place of the file: its includes still come from the file's folder.
    if (const auto stand_in = overrides().find(path); stand_in != overrides().end()) {
        text = stand_in->second;
    } else {
        std::ifstream in(resolved, std::ios::binary);
        std::ostringstream read;
        if (std::filesystem::is_regular_file(resolved) && in) read << in.rdbuf();
        if (!std::filesystem::is_regular_file(resolved) || !in || in.bad())
            throw ShaderError(
                display_path(resolved),
                "cannot read shader file '" + resolved + "'" +
                    (resolved == path ? std::string()
                                      : " ('" + path + "' in the shader directory " + shader_dir() +
                                            "; LAB_SHADER_DIR overrides it)"));
        text = read.str();
    }
    std::vector<IncludedFile> included;
    const std::string source = expand_includes(text, resolved, included);
    Shader shader = compile(stage, source, display_path(resolved), text, included);
    shader.path_ = resolved;
    return shader;
}

Shader Shader::from_source(Stage stage, const std::string& source, const std::string& name) {
    return compile(stage, source, name, source, {});
}

Shader Shader::compile(Stage stage, const std::string& source, const std::string& name,
                       const std::string& file_text, const std::vector<IncludedFile>& included) {
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
        throw ShaderError(name, format_compile_error(name, stage, log, file_text, included));
    }
    set_object_label(GL_SHADER, id, name);
    return shader;
}

}  // namespace fw
