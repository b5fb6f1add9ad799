#include "framework/gl/program.hpp"

#include <cctype>
#include <map>

#include "framework/error.hpp"
#include "framework/gl/debug.hpp"
#include "framework/text.hpp"

namespace fw {

namespace {

std::string directory_of(const std::string& path) {
    std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

// "00_pipeline/pipeline.vert + pipeline.frag": a file in the same directory as the
// one before it is shown by its name alone.
std::string joined_names(const std::vector<std::string>& files) {
    std::string out;
    for (std::size_t i = 0; i < files.size(); ++i) {
        const std::string dir = directory_of(files[i]);
        if (i == 0) {
            out = files[i];
        } else if (!dir.empty() && dir == directory_of(files[i - 1])) {
            out += " + " + files[i].substr(dir.size());
        } else {
            out += " + " + files[i];
        }
    }
    return out;
}

std::string indented(const std::string& text) {
    std::string out;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        if (end > start) out += "  " + text.substr(start, end - start) + "\n";
        start = end + 1;
    }
    return out.empty() ? "  (the linker gave no log)\n" : out;
}

bool is_identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Whether `word` occurs in `text` as a whole identifier.
bool contains_word(const std::string& text, const std::string& word) {
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
        bool start_ok = at == 0 || !is_identifier_char(text[at - 1]);
        std::size_t end = at + word.size();
        bool end_ok = end >= text.size() || !is_identifier_char(text[end]);
        if (start_ok && end_ok) return true;
    }
    return false;
}

}  // namespace

Program Program::from_files(const std::vector<std::string>& files, std::string label,
                            std::vector<std::string> feedback) {
    if (files.empty()) throw UsageError("Program::from_files: no shader files given");
    std::vector<Shader> shaders;
    for (const std::string& f : files) shaders.push_back(Shader::from_file(f));
    Program p = from_shaders(std::move(shaders), label.empty() ? joined_names(files) : label,
                             std::move(feedback));
    p.files_ = files;
    return p;
}

Program Program::from_shaders(std::vector<Shader> shaders, std::string label,
                              std::vector<std::string> feedback) {
    if (shaders.empty()) throw UsageError("Program::from_shaders: no shaders given");
    Program p;
    p.feedback_ = std::move(feedback);
    for (const Shader& s : shaders) {
        p.files_.push_back(display_path(s.path()));
        p.sources_.emplace_back(display_path(s.path()), s.source());
    }
    p.label_ = label.empty() ? joined_names(p.files_) : std::move(label);

    GLuint id = glCreateProgram();
    if (id == 0)
        throw Error("glCreateProgram failed for " + p.label_ + " (is a GL context current?)");
    p.handle_ = detail::Handle(id, [](GLuint n) { glDeleteProgram(n); });
    for (const Shader& s : shaders) glAttachShader(id, s.id());
    if (!p.feedback_.empty()) {
        std::vector<const char*> names;
        for (const std::string& n : p.feedback_) names.push_back(n.c_str());
        glTransformFeedbackVaryings(id, static_cast<GLsizei>(names.size()), names.data(),
                                    GL_INTERLEAVED_ATTRIBS);
    }
    glLinkProgram(id);
    // The linked program keeps its own copy of the code; detached shaders
    // can be deleted when `shaders` goes out of scope.
    for (const Shader& s : shaders) glDetachShader(id, s.id());

    GLint ok = GL_FALSE, log_length = 0;
    glGetProgramiv(id, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        glGetProgramiv(id, GL_INFO_LOG_LENGTH, &log_length);
        std::string log(static_cast<std::size_t>(log_length > 0 ? log_length : 0), '\0');
        if (log_length > 0) glGetProgramInfoLog(id, log_length, nullptr, log.data());
        while (!log.empty() && log.back() == '\0') log.pop_back();
        take_debug_messages();  // as for compile errors: the exception carries it
        throw ShaderError(p.label_, "program '" + p.label_ + "' failed to link (files: " +
                                        p.files_text() + "):\n" + indented(log));
    }
    set_object_label(GL_PROGRAM, id, p.label_);
    p.load_uniforms();
    return p;
}

Program Program::failed(std::vector<std::string> files, const ShaderError& error,
                        std::vector<std::string> feedback) {
    Program p;
    p.files_ = std::move(files);
    p.feedback_ = std::move(feedback);
    p.label_ = joined_names(p.files_);
    p.error_ = std::make_shared<ShaderError>(error);
    return p;
}

void Program::throw_build_error() const { throw *error_; }

void Program::use() const { glUseProgram(id()); }

// The files as paths from the source tree ("shaders/00_pipeline/pipeline.vert"),
// which a student can open from the repository root.
std::string Program::files_text() const {
    return join(sources_, ", ", [](const auto& source) { return source.first; });
}

void Program::load_uniforms() {
    const GLuint prog = id();
    GLint count = 0;
    glGetProgramInterfaceiv(prog, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
    const GLenum props[] = {GL_NAME_LENGTH, GL_TYPE, GL_ARRAY_SIZE, GL_LOCATION, GL_BLOCK_INDEX};
    for (GLint i = 0; i < count; ++i) {
        GLint values[5] = {};
        glGetProgramResourceiv(prog, GL_UNIFORM, static_cast<GLuint>(i), 5, props, 5, nullptr,
                               values);
        // Members of uniform blocks have no location; they are set through
        // the block's buffer, not with glProgramUniform.
        if (values[4] != -1 || values[3] < 0) continue;
        std::string name(static_cast<std::size_t>(values[0]), '\0');
        GLsizei length = 0;
        glGetProgramResourceName(prog, GL_UNIFORM, static_cast<GLuint>(i), values[0], &length,
                                 name.data());
        name.resize(static_cast<std::size_t>(length));

        UniformInfo info;
        info.name = name;
        info.location = values[3];
        info.type = static_cast<GLenum>(values[1]);
        info.array_size = values[2];
        // GL reports an array by its first element: "u_lights[0]".
        const std::string suffix = "[0]";
        info.is_array = name.size() > suffix.size() &&
                        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
        uniforms_[name] = info;
        if (!info.is_array) continue;
        const std::string base = name.substr(0, name.size() - suffix.size());
        uniforms_[base] = info;
        // Locations of later elements are not promised to be consecutive,
        // so each is asked for by name.
        for (GLint e = 1; e < info.array_size; ++e) {
            UniformInfo element = info;
            element.first_element = e;
            const std::string element_name = base + "[" + std::to_string(e) + "]";
            element.location = glGetProgramResourceLocation(prog, GL_UNIFORM, element_name.c_str());
            if (element.location >= 0) uniforms_[element_name] = element;
        }
    }
}

const UniformInfo* Program::uniform(const std::string& name) const {
    auto it = uniforms_.find(name);
    return it == uniforms_.end() ? nullptr : &it->second;
}

bool Program::has_uniform(const std::string& name) const { return uniform(name) != nullptr; }

std::string Program::describe_uniforms() const {
    std::map<std::string, const UniformInfo*> sorted;  // by name, as messages list them
    for (const auto& [key, info] : uniforms_)
        if (key == info.name) sorted[key] = &info;  // aliases: "u_w" and "u_w[2]" for "u_w[0]"
    const std::string out = join(sorted, ", ", [](const auto& entry) {
        const UniformInfo& info = *entry.second;
        return entry.first + ": " + glsl_type_name(info.type) +
               (info.is_array ? "[" + std::to_string(info.array_size) + "]" : std::string());
    });
    return out.empty() ? "(none)" : out;
}

std::string Program::file_declaring(const std::string& name) const {
    // The identifier at the front: "u_lights" of "u_lights[1].color".
    std::size_t end = 0;
    while (end < name.size() && is_identifier_char(name[end])) ++end;
    const std::string word = name.substr(0, end);
    std::string found_in;
    for (const auto& [file, source] : sources_)
        if (!word.empty() && contains_word(source, word)) found_in = file;
    return found_in;
}

void Program::require_declared(const std::string& name) const {
    if (id() == 0 || file_declaring(name).empty()) throw_unknown(name);
}

void Program::throw_unknown(const std::string& name) const {
    if (id() == 0) throw UsageError("Program::set('" + name + "') on an empty Program");
    std::size_t end = 0;
    while (end < name.size() && is_identifier_char(name[end])) ++end;
    const std::string word = name.substr(0, end);
    const std::string found_in = file_declaring(name);

    std::string text = "program '" + label_ + "' has no active uniform '" + name + "'";
    if (!found_in.empty())
        text += ": '" + word + "' appears in " + found_in +
                ", so it was probably optimised out: the compiler removes uniforms that do not "
                "affect the output; use it, or do not set it";
    else
        text +=
            " (misspelt? a uniform that does not affect the output may also have been "
            "optimised out)";
    text += ". Files: " + files_text() + ". Active uniforms: " + describe_uniforms();
    throw Error(text);
}

}  // namespace fw
