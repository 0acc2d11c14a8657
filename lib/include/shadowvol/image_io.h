// PNG output of rendered images and stencil counts (stb_image_write), written atomically
// (writeAtomically in mesh_io.h: a failed write leaves nothing at the path).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace shadowvol {

/// Writes `channels` (1 = grey, 3 = RGB, 4 = RGBA) 8-bit channels per pixel, rows top first as in
/// every image file. Throws InputError naming the path when the file cannot be written.
void writePng(const std::filesystem::path& path, int width, int height, int channels,
              const std::vector<std::uint8_t>& pixels);

/// Signed counts (stencil or crossing counts) as an RGB picture for a person: 0 black, +1 mid grey,
/// brighter up to +4 and beyond; negative counts red, brighter with |count|. `counts` holds one int
/// per pixel; the result 3 bytes per pixel.
std::vector<std::uint8_t> countPicture(const std::vector<int>& counts);

/// The same for 8-bit stencil counts, read as signed (wrapping: 255 is -1).
std::vector<std::uint8_t> stencilPicture(const std::vector<std::uint8_t>& stencil);

/// An 8-bit image as read from a PNG: rows top first, `channels` bytes per pixel.
struct Image8 {
  int width = 0, height = 0, channels = 0;
  std::vector<std::uint8_t> pixels;
};

/// Reads a PNG (any bit depth is converted to 8 bits) keeping its channel count, or forcing
/// `channels` (1..4) when non-zero. Throws InputError naming the path on failure.
Image8 readPng(const std::filesystem::path& path, int channels = 0);

}  // namespace shadowvol
