// An animated GIF (GIF89a) built one frame at a time in memory, for a folding shown as a picture
// (`curvefold simulate --gif`). giflib does the work: each frame is reduced to its own 256-colour
// table by GifQuantizeBuffer (Heckbert's median cut) and LZW-coded by EGifPutLine; the NETSCAPE2.0
// extension makes it loop forever and a graphics control block gives each frame its delay.
//
// Input: RGBA frames of one size (alpha ignored: the renderer's frames are opaque). Output: the
// file's bytes (write them with writeFileAtomically); only the coded frames are kept, not the
// pixels, so a long sequence costs its GIF's size in memory.
// Known limits: a frame's colours are its own 256 (smooth shading shows some banding); every frame
// is stored whole (no differences between frames).
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "engine/render/image.hpp"

namespace curvefold {

class GifAnimation {
 public:
  GifAnimation();
  ~GifAnimation();
  GifAnimation(const GifAnimation&) = delete;
  GifAnimation& operator=(const GifAnimation&) = delete;

  // Appends a frame shown for delayCentiseconds (1/100 s, at most 65535). The first frame sets
  // the picture's size; throws std::invalid_argument for an empty frame or one of another size,
  // std::runtime_error naming giflib's error.
  void addFrame(const RgbaImage& frame, unsigned delayCentiseconds);

  std::size_t frameCount() const { return frames_; }

  // The GIF's bytes; the animation takes no more frames after. Throws std::logic_error without a
  // frame.
  std::string finish();

 private:
  struct Encoder;
  std::unique_ptr<Encoder> encoder_;
  std::size_t frames_ = 0;
};

}  // namespace curvefold
