#include "engine/render/gif_animation.hpp"

#include <array>
#include <stdexcept>
#include <vector>

#include <gif_lib.h>

namespace curvefold {

namespace {

std::string giflibError(int code) {
  const char* text = GifErrorString(code);
  return text ? text : "giflib error " + std::to_string(code);
}

}  // namespace

struct GifAnimation::Encoder {
  GifFileType* file = nullptr;
  std::string bytes;
  int width = 0, height = 0;
  bool finished = false;

  ~Encoder() {
    if (file) EGifCloseFile(file, nullptr);
  }

  void check(int status, const char* what) const {
    if (status != GIF_OK)
      throw std::runtime_error(std::string("GIF encoding failed (") + what +
                               "): " + giflibError(file->Error));
  }
};

namespace {

int appendBytes(GifFileType* file, const GifByteType* data, int size) {
  static_cast<std::string*>(file->UserData)->append(reinterpret_cast<const char*>(data), size);
  return size;
}

}  // namespace

GifAnimation::GifAnimation() : encoder_(std::make_unique<Encoder>()) {}

GifAnimation::~GifAnimation() = default;

void GifAnimation::addFrame(const RgbaImage& frame, unsigned delayCentiseconds) {
  Encoder& e = *encoder_;
  if (e.finished) throw std::logic_error("GifAnimation: a frame after finish()");
  if (frame.width == 0 || frame.height == 0 || frame.width > 65535 || frame.height > 65535 ||
      frame.pixels.size() != std::size_t(frame.width) * frame.height * 4)
    throw std::invalid_argument("GIF frame: empty, larger than 65535 pixels or inconsistent");
  if (delayCentiseconds > 65535) throw std::invalid_argument("GIF frame: delay over 655.35 s");
  if (!e.file) {
    int error = 0;
    e.file = EGifOpen(&e.bytes, appendBytes, &error);
    if (!e.file)
      throw std::runtime_error(std::string("GIF encoding failed: ") + giflibError(error));
    EGifSetGifVersion(e.file, true);
    e.width = int(frame.width);
    e.height = int(frame.height);
    // No global colour table: every frame brings its own.
    e.check(EGifPutScreenDesc(e.file, e.width, e.height, 8, 0, nullptr), "screen");
    // Loop forever: the NETSCAPE2.0 application extension, loop count 0.
    const std::array<GifByteType, 3> loop{1, 0, 0};
    e.check(EGifPutExtensionLeader(e.file, APPLICATION_EXT_FUNC_CODE), "loop");
    e.check(EGifPutExtensionBlock(e.file, 11, "NETSCAPE2.0"), "loop");
    e.check(EGifPutExtensionBlock(e.file, int(loop.size()), loop.data()), "loop");
    e.check(EGifPutExtensionTrailer(e.file), "loop");
  } else if (int(frame.width) != e.width || int(frame.height) != e.height) {
    throw std::invalid_argument("GIF frame: " + std::to_string(frame.width) + "x" +
                                std::to_string(frame.height) + " after frames of " +
                                std::to_string(e.width) + "x" + std::to_string(e.height));
  }

  const std::size_t count = std::size_t(frame.width) * frame.height;
  std::vector<GifByteType> red(count), green(count), blue(count), indices(count);
  for (std::size_t i = 0; i < count; ++i) {
    red[i] = frame.pixels[4 * i];
    green[i] = frame.pixels[4 * i + 1];
    blue[i] = frame.pixels[4 * i + 2];
  }
  int colours = 256;
  std::array<GifColorType, 256> table{};
  if (GifQuantizeBuffer(frame.width, frame.height, &colours, red.data(), green.data(), blue.data(),
                        indices.data(), table.data()) != GIF_OK)
    throw std::runtime_error("GIF encoding failed: out of memory reducing a frame's colours");
  // The table is written at a power of two; the colours beyond the ones used stay black.
  const std::unique_ptr<ColorMapObject, void (*)(ColorMapObject*)> map(
      GifMakeMapObject(256, table.data()), GifFreeMapObject);
  if (!map) throw std::runtime_error("GIF encoding failed: out of memory");

  GraphicsControlBlock control{};
  control.DisposalMode = DISPOSE_DO_NOT;
  control.UserInputFlag = false;
  control.DelayTime = int(delayCentiseconds);
  control.TransparentColor = NO_TRANSPARENT_COLOR;
  std::array<GifByteType, 4> controlBytes{};
  EGifGCBToExtension(&control, controlBytes.data());
  e.check(EGifPutExtension(e.file, GRAPHICS_EXT_FUNC_CODE, int(controlBytes.size()),
                           controlBytes.data()),
          "frame delay");
  e.check(EGifPutImageDesc(e.file, 0, 0, e.width, e.height, false, map.get()), "frame");
  for (int y = 0; y < e.height; ++y)
    e.check(EGifPutLine(e.file, indices.data() + std::size_t(y) * e.width, e.width), "frame");
  ++frames_;
}

std::string GifAnimation::finish() {
  Encoder& e = *encoder_;
  if (!e.file || e.finished) throw std::logic_error("GifAnimation: finish() without frames");
  e.finished = true;
  int error = 0;
  GifFileType* file = e.file;
  e.file = nullptr;  // EGifCloseFile frees it, whatever it returns
  if (EGifCloseFile(file, &error) != GIF_OK)
    throw std::runtime_error(std::string("GIF encoding failed: ") + giflibError(error));
  return std::move(e.bytes);
}

}  // namespace curvefold
