// RGBA8 pixels read back from a render, their PNG encoding and resizing (stb).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace curvefold {

struct RgbaImage {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> pixels;  // row-major from the top, 4 bytes per pixel

  const std::uint8_t* at(std::uint32_t x, std::uint32_t y) const {
    return pixels.data() + (std::size_t(y) * width + x) * 4;
  }
};

// The PNG file's bytes (stb_image_write); write them with writeFileAtomically.
std::string encodePng(const RgbaImage& image);

// The image resampled to width x height (stb_image_resize's default filters: a box-like filter
// when shrinking, so a half-size frame is antialiased). Throws std::invalid_argument for an empty
// or inconsistent image or size.
RgbaImage resizedImage(const RgbaImage& image, std::uint32_t width, std::uint32_t height);

}  // namespace curvefold
