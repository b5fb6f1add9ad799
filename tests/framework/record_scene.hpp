// A small scene for the record's tests (test_record.cpp beside it,
// tests/grading/test_state_diff.cpp): a labelled program that reads a
// colour, a texture and one attribute, a labelled vertex array of one
// triangle, and a Recorder that observes this thread from the scene's start.
#pragma once

#include <glad/gl.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/gl/program.hpp"
#include "framework/trace/calls.hpp"
#include "framework/trace/record.hpp"

namespace record_test {

struct Scene {
    fw::gl_record::Recorder recorder;
    fw::gl_calls::Observer* saved = fw::gl_calls::observe(&recorder);
    fw::Program program;
    GLuint vao = 0, vbo = 0, texture = 0;

    Scene();
    ~Scene();
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    // The state GL starts with, for the parts the tests change.
    void reset();
    // Binds the program, the vertex array and the texture on unit 0, then draws.
    void draw();
    // The events of what `calls` does, recorded.
    template <class F>
    nlohmann::json record(F&& calls) {
        reset();
        recorder.begin();
        calls();
        return recorder.end();
    }
};

}  // namespace record_test
