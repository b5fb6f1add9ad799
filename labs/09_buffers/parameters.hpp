// Lab 9's parameters: each named once, by its handle, for params() and the
// lab's draw(); the scene is the enum draw() switches on.
#pragma once

#include <vector>

#include "framework/params.hpp"

namespace buffers {

enum class Scene { Feedback, Compute, Subdivide, Block };
constexpr fw::Choice<Scene> kScenes[] = {{Scene::Feedback, "feedback"},
                                         {Scene::Compute, "compute"},
                                         {Scene::Subdivide, "subdivide"},
                                         {Scene::Block, "block"}};

constexpr fw::ParamId<Scene> kScene{"scene"};
constexpr fw::ParamId<int> kCount{"count"};
constexpr fw::ParamId<int> kSteps{"steps"};
constexpr fw::ParamId<int> kPasses{"passes"};
constexpr fw::ParamId<float> kAngle{"angle"};

// The declaration of every parameter above, with its default, range, help
// and window key (docs/labs.md, Lab 9).
std::vector<fw::Param> params();

}  // namespace buffers
