// File checks shared by the .tri reader, the mesh loader and load_scene, so every entry point
// reports a missing file or a directory with the same one-line message.
#pragma once
#include <string>

namespace trirast {

// Throws SceneError "PATH: cannot open: <strerror>" when `path` cannot be opened for reading,
// "PATH: is a directory" when it names a directory.
void require_readable_file(const std::string& path);

// Lower-case extension of `path` including the dot (".tri"), or "" when there is none.
std::string lower_extension(const std::string& path);

}  // namespace trirast
