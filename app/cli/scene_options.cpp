#include "cli/scene_options.hpp"

namespace trirast {

std::vector<OptionSpec> scene_input_options() {
  return {
      {"--scene", "SCENE", "builtin:NAME[:k=v,...], a .tri file, or a mesh file (OBJ, PLY, STL, OFF, glTF, ...)", ""},
      {"--width", "W", "viewport width in pixels", "1024", IntRange{1, kMaxViewport}},
      {"--height", "H", "viewport height in pixels", "768", IntRange{1, kMaxViewport}},
      {"--subpixel-bits", "S", "vertex snapping: 1/2^S pixel", "8", IntRange{0, 8}},
      {"--cull", "MODE", "none | back | front (front faces run counter-clockwise as seen on screen)", "none"},
      {"--yaw", "DEG", "mesh camera: rotation about the up axis", "30"},
      {"--pitch", "DEG", "mesh camera: elevation", "20"},
      {"--distance", "R", "mesh camera: eye distance in bounding radii; 0 fits the viewport", "0"},
      {"--fov", "DEG", "mesh camera: vertical field of view", "45"},
  };
}

CameraOptions camera_from(const Args& a) {
  CameraOptions cam;
  cam.yaw_deg = a.get_double("--yaw");
  cam.pitch_deg = a.get_double("--pitch");
  cam.distance = a.get_double("--distance");
  cam.fov_deg = a.get_double("--fov");
  if (cam.fov_deg <= 0 || cam.fov_deg >= 180)
    throw UsageError("trirast " + a.command() + ": --fov: must be between 0 and 180 degrees");
  if (cam.distance < 0)
    throw UsageError("trirast " + a.command() + ": --distance: must not be negative");
  return cam;
}

}  // namespace trirast
