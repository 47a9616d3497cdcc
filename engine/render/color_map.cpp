#include "engine/render/color_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/vec3.hpp>

namespace curvefold {
namespace {

// viridis at t = 0, 1/8, ..., 1 (matplotlib's table, sRGB).
constexpr std::array<glm::vec3, 9> kViridis{{{0.267004f, 0.004874f, 0.329415f},
                                             {0.282327f, 0.140926f, 0.457517f},
                                             {0.253935f, 0.265254f, 0.529983f},
                                             {0.206756f, 0.371758f, 0.553117f},
                                             {0.163625f, 0.471133f, 0.558148f},
                                             {0.127568f, 0.566949f, 0.550556f},
                                             {0.134692f, 0.658636f, 0.517649f},
                                             {0.477504f, 0.821444f, 0.318195f},
                                             {0.993248f, 0.906157f, 0.143936f}}};
// Moreland's cool-warm at t = 0, 1/8, ..., 1 (his published table, sRGB).
constexpr std::array<glm::vec3, 9> kCoolWarm{{{0.230f, 0.299f, 0.754f},
                                              {0.353f, 0.472f, 0.887f},
                                              {0.484f, 0.629f, 0.974f},
                                              {0.619f, 0.754f, 0.999f},
                                              {0.865f, 0.865f, 0.865f},
                                              {0.958f, 0.753f, 0.652f},
                                              {0.968f, 0.607f, 0.481f},
                                              {0.906f, 0.420f, 0.324f},
                                              {0.706f, 0.016f, 0.150f}}};

}  // namespace

glm::u8vec4 colorAt(ColorMap map, double t) {
  const auto& stops = map == ColorMap::Viridis ? kViridis : kCoolWarm;
  if (!(t > 0.0)) t = 0.0;  // NaN too
  t = std::min(t, 1.0);
  const double position = t * double(stops.size() - 1);
  const std::size_t i = std::min(std::size_t(position), stops.size() - 2);
  const float f = float(position - double(i));
  const glm::vec3 c = stops[i] * (1.0f - f) + stops[i + 1] * f;
  const auto byte = [](float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  return {byte(c.r), byte(c.g), byte(c.b), 255};
}

std::vector<glm::u8vec4> colorsOf(std::span<const double> values, double low, double high,
                                  ColorMap map) {
  std::vector<glm::u8vec4> colors;
  colors.reserve(values.size());
  const double span = high - low;
  for (double v : values) {
    if (!std::isfinite(v))
      colors.push_back(colorAt(map, 0.0));
    else
      colors.push_back(colorAt(map, span > 0.0 ? (v - low) / span : 0.5));
  }
  return colors;
}

}  // namespace curvefold
