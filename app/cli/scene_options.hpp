// The options that say which scene a command sees, shared (not copied) by raster, compare and fit:
// --scene, the viewport, the snapping, culling and the mesh camera.
#pragma once
#include <vector>

#include "cli/args.hpp"
#include "scene/scene.hpp"

namespace trirast {

std::vector<OptionSpec> scene_input_options();
// The mesh camera of --yaw, --pitch, --distance, --fov; UsageError naming a bad one.
CameraOptions camera_from(const Args& a);

}  // namespace trirast
