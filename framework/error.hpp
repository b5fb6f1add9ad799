// Errors the framework throws. Every message names the thing at fault and
// what would fix it (docs/contract.md, Exit status and errors). `lab` and
// `course` print the message and exit with the code the type implies;
// nothing is swallowed.
#pragma once

#include <stdexcept>
#include <string>

namespace fw {

// A runtime failure: a shader that does not compile, a missing file, a GL error.
// Exit status 1.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A shader file that cannot be read, does not compile, or a program that
// does not link. `file()` names the file at fault ("shaders/04_geometry/
// explode.geom"), or for a link error the program ("04_geometry/a.vert +
// a.frag"). Exit status 1.
class ShaderError : public Error {
public:
    ShaderError(std::string file, const std::string& message)
        : Error(message), file_(std::move(file)) {}
    const std::string& file() const { return file_; }

private:
    std::string file_;
};

// The user asked for something that does not exist or is out of range: an
// unknown lab, parameter, enum value or checkpoint, a bad size. Exit status 2.
class UsageError : public Error {
public:
    using Error::Error;
};

// The machine lacks what the request needs: no display, no OSMesa, no EGL,
// a context that is not GL 4.3 core. Exit status 3.
class EnvironmentError : public Error {
public:
    using Error::Error;
};

inline int exit_code_for(const Error& e) {
    if (dynamic_cast<const UsageError*>(&e)) return 2;
    if (dynamic_cast<const EnvironmentError*>(&e)) return 3;
    return 1;
}

}  // namespace fw
