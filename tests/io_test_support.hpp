// Hand-made sheets and scratch directories for the file-format tests.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/geometry/sheet.hpp"

namespace curvefold::testing {

// A strip of equal panels along x, folded by hand about the vertical lines between them: panel
// i + 1 turns by angles[i] degrees (positive: toward the front, a valley) relative to panel i.
// The lines where creased[i] is true are tagged as creases (the others only bend), and the left
// end (vertices 0 and 1) is tagged as a slit. Vertex 2i is (x_i, 0), 2i + 1 is (x_i, height).
inline Sheet foldedStrip(const std::vector<double>& angles, const std::vector<bool>& creased,
                         double panelWidth = 0.05, double height = 0.1) {
  Sheet sheet;
  const std::size_t panels = angles.size() + 1;
  double theta = 0.0;  // direction of panel i in the xz plane
  glm::dvec3 origin(0.0);
  for (std::size_t i = 0; i <= panels; ++i) {
    const double x = panelWidth * static_cast<double>(i);
    sheet.development.push_back({x, 0.0});
    sheet.development.push_back({x, height});
    sheet.positions.push_back(origin);
    sheet.positions.push_back(origin + glm::dvec3(0.0, height, 0.0));
    origin += panelWidth * glm::dvec3(std::cos(theta), 0.0, std::sin(theta));
    if (i < angles.size()) theta += angles[i] * std::numbers::pi / 180.0;
  }
  for (VertexIndex i = 0; i < panels; ++i) {
    const VertexIndex b = 2 * i;
    sheet.triangles.push_back({b, b + 2, b + 3});
    sheet.triangles.push_back({b, b + 3, b + 1});
    if (i < creased.size() && creased[i])
      sheet.tags.push_back({Edge::of(b + 2, b + 3), EdgeKind::Crease});
  }
  sheet.tags.push_back({Edge::of(0, 1), EdgeKind::Slit});
  sheet.normalizeTags();
  return sheet;
}

// Five panels: a 90 degree valley crease, a 60 degree mountain crease, a 10 degree bend (not a
// crease) and a crease unfolded flat.
inline Sheet testStrip() {
  return foldedStrip({90.0, -60.0, 10.0, 0.0}, {true, true, false, true});
}

// A fresh directory per test, removed afterwards.
class ScratchDirectory : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("curvefold-io-" + std::to_string(::getpid()) + "-" + info->test_suite_name() + "-" +
            info->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  const std::filesystem::path& dir() const { return dir_; }

  // Names of the directory's entries, sorted.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir_))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  static std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

 private:
  std::filesystem::path dir_;
};

}  // namespace curvefold::testing
