#include "engine/render/image.hpp"

#include <stdexcept>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb/stb_image_write.h>
#define STB_IMAGE_RESIZE_IMPLEMENTATION
#include <stb/stb_image_resize.h>

namespace curvefold {

std::string encodePng(const RgbaImage& image) {
  if (image.width == 0 || image.height == 0 ||
      image.pixels.size() != std::size_t(image.width) * image.height * 4)
    throw std::invalid_argument("encodePng: empty or inconsistent image");
  std::string bytes;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), size);
  };
  if (!stbi_write_png_to_func(append, &bytes, static_cast<int>(image.width),
                              static_cast<int>(image.height), 4, image.pixels.data(),
                              static_cast<int>(image.width * 4)))
    throw std::runtime_error("PNG encoding failed");
  return bytes;
}

RgbaImage resizedImage(const RgbaImage& image, std::uint32_t width, std::uint32_t height) {
  if (image.width == 0 || image.height == 0 || width == 0 || height == 0 ||
      image.pixels.size() != std::size_t(image.width) * image.height * 4)
    throw std::invalid_argument("resizedImage: empty or inconsistent image or size");
  RgbaImage out{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4)};
  if (!stbir_resize_uint8(image.pixels.data(), int(image.width), int(image.height), 0,
                          out.pixels.data(), int(width), int(height), 0, 4))
    throw std::runtime_error("resizedImage: out of memory");
  return out;
}

}  // namespace curvefold
