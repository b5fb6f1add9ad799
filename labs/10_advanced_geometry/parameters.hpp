// Lab 10's parameters: each named once, by its handle, for params() and the
// lab's draw(); the scene is the enum draw() switches on.
#pragma once

#include <vector>

#include "framework/params.hpp"

namespace advanced_geometry {

enum class Scene { Instances, Clip, Layers, Silhouette };
constexpr fw::Choice<Scene> kScenes[] = {{Scene::Instances, "instances"},
                                         {Scene::Clip, "clip"},
                                         {Scene::Layers, "layers"},
                                         {Scene::Silhouette, "silhouette"}};

constexpr fw::ParamId<Scene> kScene{"scene"};
constexpr fw::ParamId<int> kColumns{"columns"};
constexpr fw::ParamId<int> kRows{"rows"};
constexpr fw::ParamId<float> kClipAngle{"clip_angle"};
constexpr fw::ParamId<float> kClipOffset{"clip_offset"};
constexpr fw::ParamId<int> kFaceSize{"face_size"};
constexpr fw::ParamId<float> kYaw{"yaw"};
constexpr fw::ParamId<float> kPitch{"pitch"};

constexpr int kMaxCells = 8;  // columns and rows

// The declaration of every parameter above, with its default, range, help
// and window key (docs/labs.md, Lab 10).
std::vector<fw::Param> params();

}  // namespace advanced_geometry
