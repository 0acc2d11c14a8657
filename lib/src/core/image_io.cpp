#include "shadowvol/image_io.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>

#include <stb_image.h>
#include <stb_image_write.h>

#include "shadowvol/check.h"
#include "shadowvol/error.h"
#include "shadowvol/mesh_io.h"

namespace shadowvol {

void writePng(const std::filesystem::path& path, int width, int height, int channels,
              const std::vector<std::uint8_t>& pixels) {
  SV_CHECK(channels == 1 || channels == 3 || channels == 4);
  SV_CHECK_EQ(pixels.size(), std::size_t(width) * std::size_t(height) * std::size_t(channels));
  // Encoded in memory and written through a checked stream: stbi_write_png's own file writing
  // does not report a failed write (a full disk left a truncated PNG in place, exit 0).
  std::string png;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
  };
  if (!stbi_write_png_to_func(append, &png, width, height, channels, pixels.data(), width * channels))
    throw InputError(path.string(), "", "", "cannot encode the PNG image");
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError(path.string(), "", "", "cannot create the file");
    out.write(png.data(), std::streamsize(png.size()));
    out.close();
    if (!out) throw InputError(path.string(), "", "", "writing the file failed (disk full?)");
  });
}

Image8 readPng(const std::filesystem::path& path, int channels) {
  SV_CHECK(channels >= 0 && channels <= 4);
  int w = 0, h = 0, n = 0;
  stbi_uc* data = stbi_load(path.string().c_str(), &w, &h, &n, channels);
  if (!data) {
    const char* why = stbi_failure_reason();
    throw InputError(path.string(), "", "", std::string("cannot read the PNG file: ") + (why ? why : "unknown error"));
  }
  Image8 img;
  img.width = w;
  img.height = h;
  img.channels = channels ? channels : n;
  img.pixels.assign(data, data + std::size_t(w) * std::size_t(h) * std::size_t(img.channels));
  stbi_image_free(data);
  return img;
}

std::vector<std::uint8_t> countPicture(const std::vector<int>& counts) {
  std::vector<std::uint8_t> rgb(counts.size() * 3, 0);
  for (std::size_t k = 0; k < counts.size(); ++k) {
    const int c = counts[k];
    if (c == 0) continue;
    const auto level = std::uint8_t(100 + 38 * std::min(std::abs(c), 4));
    rgb[3 * k] = level;
    rgb[3 * k + 1] = rgb[3 * k + 2] = c > 0 ? level : 0;
  }
  return rgb;
}

std::vector<std::uint8_t> stencilPicture(const std::vector<std::uint8_t>& stencil) {
  std::vector<int> counts(stencil.size());
  for (std::size_t k = 0; k < stencil.size(); ++k) counts[k] = stencil[k] > 127 ? int(stencil[k]) - 256 : int(stencil[k]);
  return countPicture(counts);
}

}  // namespace shadowvol
