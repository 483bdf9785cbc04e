// Scene entry points: the file checks and load_scene's dispatch on the argument.
#include "scene/scene.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>

#include "scene/scene_files.hpp"

namespace trirast {

void require_readable_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw SceneError(path + ": cannot open: " + std::strerror(errno));
  struct stat st;
  const bool is_dir = ::fstat(fd, &st) == 0 && S_ISDIR(st.st_mode);
  ::close(fd);
  if (is_dir) throw SceneError(path + ": is a directory");
}

std::string lower_extension(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

Scene load_scene(const std::string& arg, const RasterConfig& cfg, const CameraOptions& cam) {
  static const std::string kBuiltinPrefix = "builtin:";
  if (arg.compare(0, kBuiltinPrefix.size(), kBuiltinPrefix) == 0) {
    Scene scene = make_builtin(arg.substr(kBuiltinPrefix.size()), cfg, cam);
    scene.name = arg;
    return scene;
  }
  require_readable_file(arg);
  Scene scene = lower_extension(arg) == ".tri" ? read_tri_file(arg) : load_mesh(arg, cfg, cam);
  scene.name = arg;
  return scene;
}

}  // namespace trirast
