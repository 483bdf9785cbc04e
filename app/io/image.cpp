#include "io/image.hpp"

#include <png.h>

#include <algorithm>

#include "io/output_file.hpp"

namespace trirast {

void RgbImage::fill_span(const Span& s, uint8_t r, uint8_t g, uint8_t b) {
  if (s.y < 0 || s.y >= height) return;
  const int x0 = std::max(0, s.x_begin), x1 = std::min(width, s.x_end);
  if (x0 >= x1) return;
  uint8_t* p = &rgb[(size_t(s.y) * width + x0) * 3];
  for (int x = x0; x < x1; ++x, p += 3) {
    p[0] = r;
    p[1] = g;
    p[2] = b;
  }
}

void triangle_colour(uint32_t tri, uint8_t rgb[3]) {
  uint32_t h = tri * 2654435761u;  // Knuth's multiplicative hash spreads neighbours apart
  h ^= h >> 15;
  for (int c = 0; c < 3; ++c) rgb[c] = uint8_t(64 + ((h >> (8 * c)) & 0xff) % 192);
}

RgbImage coverage_image(const SpanList& spans, int width, int height) {
  RgbImage img(width, height);
  uint8_t c[3];
  for (const Span& s : spans) {
    triangle_colour(s.tri, c);
    img.fill_span(s, c[0], c[1], c[2]);
  }
  return img;
}

RgbImage diff_image(const SpanList& golden, const SpanDiff& diff, int width, int height) {
  RgbImage img(width, height);
  for (const Span& s : golden) img.fill_span(s, 128, 128, 128);
  // Extra first, missing last: a baseline's extra pixels are common and must not hide a miss.
  // Each differing pixel is ringed (a square outline, radius ~1% of the image, at least 3 px)
  // in its colour, so a handful of them show at any size; the pixels themselves are drawn last.
  const int radius = std::max(3, std::max(width, height) / 100);
  auto ring = [&](const Span& s, uint8_t r, uint8_t g, uint8_t b) {
    for (int x = s.x_begin; x < s.x_end; ++x) {
      img.fill_span(Span{s.tri, s.y - radius, x - radius, x + radius + 1}, r, g, b);
      img.fill_span(Span{s.tri, s.y + radius, x - radius, x + radius + 1}, r, g, b);
      for (int y = s.y - radius + 1; y < s.y + radius; ++y) {
        img.fill_span(Span{s.tri, y, x - radius, x - radius + 1}, r, g, b);
        img.fill_span(Span{s.tri, y, x + radius, x + radius + 1}, r, g, b);
      }
    }
  };
  // (Many differing pixels show by themselves: rings only up to 20,000 of them.)
  if (diff.missing_pixels + diff.extra_pixels <= 20000) {
    for (const Span& s : diff.extra) ring(s, 40, 90, 255);
    for (const Span& s : diff.missing) ring(s, 230, 30, 30);
  }
  for (const Span& s : diff.extra) img.fill_span(s, 40, 90, 255);
  for (const Span& s : diff.missing) img.fill_span(s, 230, 30, 30);
  return img;
}

void write_png(const RgbImage& image, const std::string& path, const std::string& option) {
  OutputFile out(path, option);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, &info);
    throw OutputError(option + " " + path + ": libpng could not start");
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw OutputError(option + " " + path + ": PNG encoding failed");
  }
  png_init_io(png, out.stream());
  png_set_IHDR(png, info, image.width, image.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y)
    png_write_row(png, const_cast<png_bytep>(&image.rgb[size_t(y) * image.width * 3]));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  out.commit();
}

}  // namespace trirast
