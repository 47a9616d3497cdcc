#include "engine/render/image.hpp"

#include <stdexcept>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb/stb_image_write.h>

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

}  // namespace curvefold
