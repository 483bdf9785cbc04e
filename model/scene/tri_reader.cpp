// The .tri text format: one triangle "x0 y0 x1 y1 x2 y2" per line, '#' comments, blank lines.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "scene/scene.hpp"
#include "scene/scene_files.hpp"

namespace trirast {

namespace {

// Whitespace inside a line. '\n' ends a line and is handled by the caller.
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// NUL and control characters other than whitespace never occur in a text file.
bool is_binary_byte(unsigned char c) {
  return (c < 0x20 && c != '\n' && !is_blank(char(c))) || c == 0x7f;
}

bool has_binary_bytes(const char* data, size_t size) {
  for (size_t i = 0; i < size; ++i)
    if (is_binary_byte(static_cast<unsigned char>(data[i]))) return true;
  return false;
}

// A token quoted for an error message, shortened so the message stays one readable line.
std::string quote_token(const char* begin, const char* end) {
  constexpr size_t kMaxShown = 40;
  const size_t len = size_t(end - begin);
  if (len <= kMaxShown) return "'" + std::string(begin, len) + "'";
  return "'" + std::string(begin, kMaxShown) + "...'";
}

// Parses the numbers of one line [begin, end) (comment already cut off). Returns how many
// tokens the line holds; fills `out` with the first six.
size_t parse_line(const char* begin, const char* end, double out[6], const std::string& where) {
  size_t count = 0;
  const char* p = begin;
  while (true) {
    while (p < end && is_blank(*p)) ++p;
    if (p == end) return count;
    const char* token_end = p;
    while (token_end < end && !is_blank(*token_end)) ++token_end;
    // strtod stops at the blank, '#', '\n' or NUL after the token; anything it leaves inside
    // the token is trailing garbage. nan/inf are numbers here (setup rejects them with the
    // triangle index), and an overflow such as 1e999 likewise comes back as inf.
    char* number_end = nullptr;
    const double value = std::strtod(p, &number_end);
    if (number_end != token_end)
      throw SceneError(where + ": " + quote_token(p, token_end) + " is not a number");
    if (count < 6) out[count] = value;
    ++count;
    p = token_end;
  }
}

}  // namespace

Scene parse_tri_text(const std::string& text, const std::string& name) {
  if (has_binary_bytes(text.data(), text.size()))
    throw SceneError(name + ": binary data, not a .tri text file");
  Scene scene;
  scene.name = name;
  const char* p = text.c_str();
  const char* const text_end = p + text.size();
  for (int line = 1; p < text_end; ++line) {
    const char* line_end = static_cast<const char*>(std::memchr(p, '\n', size_t(text_end - p)));
    if (!line_end) line_end = text_end;
    const char* hash = static_cast<const char*>(std::memchr(p, '#', size_t(line_end - p)));
    const char* content_end = hash ? hash : line_end;
    const std::string where = name + ":" + std::to_string(line);
    double v[6];
    const size_t found = parse_line(p, content_end, v, where);
    if (found != 0 && found != 6)
      throw SceneError(where + ": expected 6 numbers, found " + std::to_string(found));
    if (found == 6) {
      InputTriangle tri;
      for (int i = 0; i < 3; ++i) {
        tri.x[i] = v[2 * i];
        tri.y[i] = v[2 * i + 1];
      }
      tri.line = line;
      scene.tris.push_back(tri);
    }
    p = line_end + 1;
  }
  if (scene.tris.empty()) throw SceneError(name + ": empty scene (no triangles)");
  return scene;
}

Scene read_tri_file(const std::string& path) {
  require_readable_file(path);
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw SceneError(path + ": cannot open: " + std::strerror(errno));
  // Read in chunks and look for binary bytes as we go, so /dev/zero or a huge binary file is
  // refused after the first chunk instead of being read to the end.
  std::string text;
  char chunk[1 << 16];
  size_t got;
  while ((got = std::fread(chunk, 1, sizeof chunk, file.get())) > 0) {
    if (has_binary_bytes(chunk, got)) throw SceneError(path + ": binary data, not a .tri text file");
    text.append(chunk, got);
  }
  if (std::ferror(file.get())) throw SceneError(path + ": read error: " + std::strerror(errno));
  return parse_tri_text(text, path);
}

}  // namespace trirast
