// `curvefold simulate` (issue 39, 3): outputs all or none, one-line errors, the folding as frames
// and as an animated GIF.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gif_lib.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "test_paths.hpp"

namespace curvefold::testing {
namespace {

class SimulateCli : public CliTest {};

TEST_F(SimulateCli, WritesTheSettledStateAsObjAndFoldWithItsFoldedFrame) {
  ASSERT_EQ(run("new cone --resolution 12 -o c.curvefold.json").exitCode, 0);
  const CommandResult result =
      run("simulate c.curvefold.json --percent 0:100:3 --settle --obj c.obj --fold c.fold");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_NE(result.out.find("100%: settled"), std::string::npos) << result.out;
  const nlohmann::json fold = nlohmann::json::parse(slurp(path("c.fold")));
  ASSERT_EQ(fold["file_frames"].size(), 1u);
  const auto& folded = fold["file_frames"][0]["vertices_coords"];
  ASSERT_EQ(folded.size(), fold["vertices_coords"].size());
  // The folded frame is 3D and not flat: the cone's sheet bends out of its plane.
  double zRange = 0.0;
  for (const auto& p : folded) zRange = std::max(zRange, std::abs(p[2].get<double>()));
  EXPECT_GT(zRange, 1e-3);
  EXPECT_NE(slurp(path("c.obj")).find("\nf "), std::string::npos);
}

// Issue 39, 1: design mode is the command's default for a curvefold design, as in the live
// window and Python's Design.simulate: at 100% the settled state is the design itself, up to a
// rigid motion (every pairwise vertex distance as in the design's own OBJ).
TEST_F(SimulateCli, ADesignAtFullAmountIsTheDesignItself) {
  ASSERT_EQ(run("new cone --resolution 12 -o c.curvefold.json").exitCode, 0);
  ASSERT_EQ(run("export c.curvefold.json --obj design.obj").exitCode, 0);
  const CommandResult result = run("simulate c.curvefold.json --percent 100 --settle --obj s.obj");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  auto vertices = [&](const std::string& name) {
    std::vector<std::array<double, 3>> out;
    std::istringstream in(slurp(path(name)));
    for (std::string line; std::getline(in, line);) {
      std::istringstream words(line);
      std::string tag;
      std::array<double, 3> p{};
      if (words >> tag && tag == "v" && words >> p[0] >> p[1] >> p[2]) out.push_back(p);
    }
    return out;
  };
  const auto design = vertices("design.obj"), simulated = vertices("s.obj");
  ASSERT_EQ(simulated.size(), design.size());
  ASSERT_GT(design.size(), 10u);
  auto distance = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  };
  double size = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < design.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) {
      size = std::max(size, distance(design[i], design[j]));
      largest = std::max(
          largest, std::abs(distance(design[i], design[j]) - distance(simulated[i], simulated[j])));
    }
  EXPECT_LT(largest, 1e-6 * size) << "largest change of a vertex distance " << largest;
}

TEST_F(SimulateCli, BadOptionsAreOneLineAndWriteNothing) {
  ASSERT_EQ(run("new square -o s.curvefold.json").exitCode, 0);
  for (const std::string options :
       {"--percent 120 --obj s.obj", "--percent nan --obj s.obj", "--percent 0:100:1 --obj s.obj",
        "--percent 50 --paper 0 --obj s.obj", "--percent 50 --glue 0,0 --obj s.obj", "--percent 50",
        "--percent 50 --obj s.obj --fold missing-folder/s.fold",
        "--percent 50 --stiffness soft --obj s.obj", "--percent 50 --crease-side -1 --obj s.obj",
        "--percent 50 --stiffness origami-simulator --paper 0.1 --obj s.obj"}) {
    const CommandResult result = run("simulate s.curvefold.json " + options);
    EXPECT_EQ(result.exitCode, 1) << options;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1)
        << options << ": " << result.err;
    EXPECT_FALSE(fs::exists(path("s.obj"))) << options;
  }
  const CommandResult fold = run("simulate other.fold --percent 50 --obj s.obj");
  EXPECT_EQ(fold.exitCode, 1);
  EXPECT_NE(fold.err.find("other.fold"), std::string::npos) << fold.err;
}

// What the reader read otherwise than written reaches the user: each note of the crease pattern
// on stderr, "note: ..." (a malformed width among them); the size line says what size it took.
// Before, the notes were kept in the pattern and never shown by simulate.
TEST_F(SimulateCli, ACreasePatternsNotesAreShown) {
  std::ofstream(path("q.svg"))
      << R"(<svg xmlns="http://www.w3.org/2000/svg" width="12qq" viewBox="0 0 20 10">
      <rect width="20" height="10" stroke="black" fill="none"/>
      <line x1="10" y1="0" x2="10" y2="10" stroke="blue" stroke-opacity="0.5"/></svg>)";
  const CommandResult result = run("simulate q.svg --percent 50 --steps 10 --obj q.obj");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_NE(result.err.find("note: <svg width=\"12qq\">: unknown unit \"qq\""), std::string::npos)
      << result.err;
  EXPECT_EQ(result.out.rfind("sheet 5.292 x 2.646 mm (no width or height in an absolute unit", 0),
            0u)
      << result.out;
  fs::remove(path("q.obj"));
}

// A crease pattern is simulated at the size its file states (an SVG's width and height against
// its viewBox), said on the first line, or at --size's; --size is refused for a design (in metres
// already) and outside (0, 1 km], in one line, writing nothing.
TEST_F(SimulateCli, ACreasePatternIsSimulatedAtItsStatedSizeOrAtSizes) {
  std::ofstream(path("p.svg"))
      << R"(<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="100mm" viewBox="0 0 20 10">
      <rect width="20" height="10" stroke="black" fill="none"/>
      <line x1="10" y1="0" x2="10" y2="10" stroke="blue" stroke-opacity="0.5"/></svg>)";
  const CommandResult stated = run("simulate p.svg --percent 50 --settle --obj p.obj");
  ASSERT_EQ(stated.exitCode, 0) << stated.err;
  EXPECT_EQ(stated.out.rfind("sheet 200 x 100 mm (width and height in mm", 0), 0u) << stated.out;
  const CommandResult sized = run("simulate p.svg --percent 50 --settle --size 50 --obj p.obj");
  ASSERT_EQ(sized.exitCode, 0) << sized.err;
  EXPECT_EQ(sized.out.rfind("sheet 50 x 25 mm (--size)", 0), 0u) << sized.out;
  fs::remove(path("p.obj"));
  ASSERT_EQ(run("new square -o s.curvefold.json").exitCode, 0);
  for (const std::string arguments :
       {"s.curvefold.json --percent 50 --size 100 --obj p.obj",
        "p.svg --percent 50 --size 0 --obj p.obj", "p.svg --percent 50 --size nan --obj p.obj"}) {
    const CommandResult result = run("simulate " + arguments);
    EXPECT_EQ(result.exitCode, 1) << arguments;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find("--size"), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(path("p.obj"))) << arguments;
  }
}

// Every option of simulate left without its value (or given one CLI11 refuses) exits 1 with one
// line naming it, never CLI11's own exit codes (106 for a missing option, 109 for an extra
// argument, 114 for a missing value).
TEST_F(SimulateCli, CommandLinesCli11RefusesExitOneWithOneLine) {
  ASSERT_EQ(run("new square -o s.curvefold.json").exitCode, 0);
  const std::string base = "simulate s.curvefold.json --percent 50 --obj s.obj ";
  std::vector<std::pair<std::string, std::string>> cases = {
      {"simulate s.curvefold.json --obj s.obj", "--percent"},
      {"simulate --percent 50 --obj s.obj", "INPUT"},
      {"simulate s.curvefold.json --obj s.obj --percent", "--percent"},
      {base + "--bogus", "--bogus"},
      {base + "--steps x", "--steps"}};
  for (const char* option :
       {"--steps", "--paper", "--stiffness", "--modulus", "--pin", "--glue", "--fold", "--gltf",
        "--png", "--frames", "--color", "--gif", "--crease-side"})
    cases.emplace_back(base + option, option);
  cases.emplace_back("simulate s.curvefold.json --percent 50 --png s.png --color", "--color");
  cases.emplace_back("simulate s.curvefold.json --percent 50 --color --png s.png", "--color");
  for (const auto& [arguments, fragment] : cases) {
    const CommandResult result = run(arguments);
    EXPECT_EQ(result.exitCode, 1) << arguments << ": " << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1)
        << arguments << ": " << result.err;
    EXPECT_NE(result.err.find(fragment), std::string::npos) << arguments << ": " << result.err;
    EXPECT_FALSE(fs::exists(path("s.obj"))) << arguments;
  }
}

// --pin and --glue take points on the flat sheet in metres; a point off the sheet (here one in
// millimetres on a 40 mm sheet) is refused in one line naming the sheet's extent, writing nothing,
// not pinned to the nearest corner; a point on the sheet's corner is taken.
TEST_F(SimulateCli, APinOrGlueOffTheFlatSheetIsRefused) {
  std::ofstream(path("flat.fold"))
      << R"({"file_spec": 1.1, "vertices_coords": [[0, 0], [0.02, 0], [0.04, 0], [0.04, 0.04],
      [0.02, 0.04], [0, 0.04]], "faces_vertices": [[0, 1, 4, 5], [1, 2, 3, 4]],
      "edges_vertices": [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0], [1, 4]],
      "edges_assignment": ["B", "B", "B", "B", "B", "B", "V"],
      "edges_foldAngle": [0, 0, 0, 0, 0, 0, 90]})";
  const std::string base = "simulate flat.fold --percent 50 --paper 0.1 --obj p.obj ";
  for (const auto& [extra, fragment] : std::vector<std::pair<std::string, std::string>>{
           {"--pin 40,40", "--pin: (40, 40) is off the flat sheet"},
           {"--glue 0,0:40,0", "--glue: (40, 0) is off the flat sheet"}}) {
    const CommandResult result = run(base + extra);
    EXPECT_EQ(result.exitCode, 1) << extra;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find(fragment), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(path("p.obj"))) << extra;
  }
  const CommandResult corner = run(base + "--pin 0.04,0.04");
  EXPECT_EQ(corner.exitCode, 0) << corner.err;
  EXPECT_TRUE(fs::exists(path("p.obj")));
}

// Paper mode's self-contact, said and checked: a 40 mm sheet with one valley folded flat keeps its
// layers the thickness apart, says so and that the state does not pass through itself, and
// `check` of the written state agrees; --no-contact turns it off, and is refused without --paper.
TEST_F(SimulateCli, PaperModeSaysItsContactAndWhetherTheStatePassesThroughItself) {
  std::ofstream(path("flat.fold"))
      << R"({"file_spec": 1.1, "vertices_coords": [[0, 0], [0.02, 0], [0.04, 0], [0.04, 0.04],
      [0.02, 0.04], [0, 0.04]], "faces_vertices": [[0, 1, 4, 5], [1, 2, 3, 4]],
      "edges_vertices": [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0], [1, 4]],
      "edges_assignment": ["B", "B", "B", "B", "B", "B", "V"]})";
  const CommandResult result =
      run("simulate flat.fold --percent 100 --settle --paper 0.1 --obj folded.obj");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_NE(result.out.find("self-contact: layers kept 0.1 mm apart"), std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find(", self-intersection: none"), std::string::npos) << result.out;
  const CommandResult check = run("check folded.obj");
  EXPECT_EQ(check.exitCode, 0) << check.out << check.err;
  EXPECT_NE(check.out.find("no self-intersection"), std::string::npos) << check.out;
  const CommandResult off =
      run("simulate flat.fold --percent 100 --settle --paper 0.1 --no-contact --obj off.obj");
  ASSERT_EQ(off.exitCode, 0) << off.err;
  EXPECT_NE(off.out.find("self-contact: off"), std::string::npos) << off.out;
  const CommandResult refused = run("simulate flat.fold --percent 100 --no-contact --obj d.obj");
  EXPECT_EQ(refused.exitCode, 1);
  EXPECT_NE(refused.err.find("--no-contact: only paper mode"), std::string::npos) << refused.err;
}

// Edges against edges in paper mode: a flat-foldable degree-4 vertex
// (bench/make_audit_patterns.py's vertex4_s7, copied) settles with one triangle pair crossing where
// only vertex-triangle pairs keep the layers apart (an edge passes through an edge); with edge
// pairs it settles, none.
TEST_F(SimulateCli, PaperModeKeepsEdgesFromPassingThroughEdges) {
  const std::string pattern = std::string(CURVEFOLD_TEST_DATA) + "/crease_patterns/vertex4_s7.fold";
  const CommandResult result =
      run("simulate " + pattern + " --percent 100 --settle --paper 0.1 --obj v.obj");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_NE(result.out.find("100%: settled in "), std::string::npos) << result.out;
  EXPECT_NE(result.out.find(", self-intersection: none"), std::string::npos) << result.out;
}

// A stall short of the rounding floor is tried again from the stage's first damping
// (static_solver.cpp): a Miura-ori in quads with a 3D frame (miura_quads_frames.fold,
// bench/make_judge_patterns.py's, a 6 m sheet read as metres) folded 25:100:4 in paper mode
// stalled at its 75% state, residual 2.8e-9 (2.3 times its floor) with the damping at 3.2e10 of
// the diagonal, its steps too short to move a coordinate; from 1e-6 again it reaches its floor
// (1.3e-9), and every state settles (to the tolerance, or at the floor).
TEST_F(SimulateCli, AStallTriedAgainFromTheFirstDampingSettlesEveryPaperMiuraState) {
  const std::string pattern =
      std::string(CURVEFOLD_TEST_DATA) + "/crease_patterns/miura_quads_frames.fold";
  const CommandResult result =
      run("simulate " + pattern + " --percent 25:100:4 --settle --paper 0.1 --obj m.obj");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  for (const char* state : {"25%: settled ", "50%: settled ", "75%: settled ", "100%: settled "})
    EXPECT_NE(result.out.find(state), std::string::npos) << state << "\n" << result.out;
  EXPECT_EQ(result.out.find("NOT settled"), std::string::npos) << result.out;
}

// --motion: the waterbomb base settles on its targets at 50% (about 44 degrees off them with the
// targets scaled linearly), and says how far its motion was followed.
TEST_F(SimulateCli, MotionBringsTheWaterbombOntoItsTargets) {
  const std::string pattern =
      std::string(CURVEFOLD_TEST_DATA) + "/crease_patterns/waterbomb_base.fold";
  auto worstError = [&](const std::string& extra) {
    const CommandResult result =
        run("simulate " + pattern + " --percent 50 --settle --obj w.obj" + extra);
    EXPECT_EQ(result.exitCode, 0) << result.err;
    const std::size_t at = result.out.find("largest crease angle error ");
    EXPECT_NE(at, std::string::npos) << result.out;
    return at == std::string::npos ? 1e9 : std::stod(result.out.substr(at + 27));
  };
  EXPECT_GT(worstError(""), 20.0);
  EXPECT_LT(worstError(" --motion"), 0.5);
  const CommandResult result =
      run("simulate " + pattern + " --percent 50 --settle --motion --obj w.obj");
  EXPECT_NE(result.out.find("folding motion: "), std::string::npos) << result.out;
}

// --stiffness origami-simulator: facets as soft as creases (Origami Simulator's), so the sheet
// bends between the curved pleat's creases and they come far closer to their angles than with
// the project's stiff facets (23 degrees off at most, 7 with Origami Simulator's).
TEST_F(SimulateCli, OrigamiSimulatorStiffnessesBringACurvedPleatCloser) {
  const std::string pattern =
      std::string(CURVEFOLD_TEST_DATA) + "/crease_patterns/curved_pleat.fold";
  auto worstError = [&](const std::string& extra) {
    const CommandResult result =
        run("simulate " + pattern + " --percent 100 --settle --obj p.obj" + extra);
    EXPECT_EQ(result.exitCode, 0) << result.err;
    const std::size_t at = result.out.find("largest crease angle error ");
    EXPECT_NE(at, std::string::npos) << result.out;
    return at == std::string::npos ? 1e9 : std::stod(result.out.substr(at + 27));
  };
  const double stiffFacets = worstError("");
  const double simulator = worstError(" --stiffness origami-simulator");
  EXPECT_GT(stiffFacets, 15.0);
  EXPECT_LT(simulator, 10.0);
  EXPECT_NEAR(worstError(" --stiffness curvefold"), stiffFacets, 1e-9);
}

// --gpu takes the dynamic steps with the targets scaled by --percent: with --motion (targets along
// the pattern's motion, CPU only) or --settle (the CPU's static solver) it would silently do
// something else than asked, so each pair is refused in one line naming both, writing nothing.
TEST_F(SimulateCli, GpuWithMotionOrSettleIsRefusedInOneLine) {
  const std::string pattern =
      std::string(CURVEFOLD_TEST_DATA) + "/crease_patterns/waterbomb_base.fold";
  for (const std::string other : {"--motion", "--settle"}) {
    fs::remove(path("w.obj"));
    const CommandResult result =
        run("simulate " + pattern + " --percent 50 --gpu " + other + " --obj w.obj");
    EXPECT_EQ(result.exitCode, 1) << other << ": " << result.out << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find("--gpu"), std::string::npos) << result.err;
    EXPECT_NE(result.err.find(other), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(path("w.obj"))) << other;
  }
}

// A GIF decoded by giflib: its screen size, each frame's RGB pixels and delay (centiseconds), and
// whether it loops (NETSCAPE2.0). Empty frames when it is no GIF.
struct DecodedGif {
  int width = 0, height = 0;
  bool loops = false;
  std::vector<std::vector<std::uint8_t>> frames;
  std::vector<int> delays;
};

DecodedGif decodeGif(const fs::path& path) {
  DecodedGif decoded;
  int error = 0;
  GifFileType* gif = DGifOpenFileName(path.c_str(), &error);
  if (!gif) return decoded;
  if (DGifSlurp(gif) == GIF_OK) {
    decoded.width = gif->SWidth;
    decoded.height = gif->SHeight;
    for (int i = 0; i < gif->ImageCount; ++i) {
      const SavedImage& image = gif->SavedImages[i];
      const ColorMapObject* map =
          image.ImageDesc.ColorMap ? image.ImageDesc.ColorMap : gif->SColorMap;
      if (!map || image.ImageDesc.Width != gif->SWidth || image.ImageDesc.Height != gif->SHeight)
        return {};
      std::vector<std::uint8_t> rgb;
      for (int p = 0; p < gif->SWidth * gif->SHeight; ++p) {
        const GifColorType c = map->Colors[image.RasterBits[p]];
        rgb.insert(rgb.end(), {c.Red, c.Green, c.Blue});
      }
      decoded.frames.push_back(std::move(rgb));
      GraphicsControlBlock control{};
      decoded.delays.push_back(
          DGifSavedExtensionToGCB(gif, i, &control) == GIF_OK ? control.DelayTime : -1);
      for (int e = 0; e < image.ExtensionBlockCount; ++e)
        if (image.ExtensionBlocks[e].Function == APPLICATION_EXT_FUNC_CODE &&
            image.ExtensionBlocks[e].ByteCount == 11 &&
            std::string(reinterpret_cast<const char*>(image.ExtensionBlocks[e].Bytes), 11) ==
                "NETSCAPE2.0")
          decoded.loops = true;
    }
  }
  DGifCloseFile(gif, &error);
  return decoded;
}

// The share of pixels that differ by more than a little between two frames.
double changedShare(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  std::size_t changed = 0;
  for (std::size_t p = 0; p + 2 < a.size(); p += 3)
    if (std::abs(a[p] - b[p]) + std::abs(a[p + 1] - b[p + 1]) + std::abs(a[p + 2] - b[p + 2]) > 24)
      ++changed;
  return double(changed) / double(a.size() / 3);
}

// The GIF holds one frame per state, of half the PNG's size, looping, 0.1 s a frame and the last
// held a second; each frame shows its own state (the sheet folds from frame to frame: none repeats
// another, which the renderer's stale upload did after the first two).
TEST_F(SimulateCli, WritesTheFoldingAsAnAnimatedGif) {
  ASSERT_EQ(run("new cone --resolution 12 -o c.curvefold.json").exitCode, 0);
  const CommandResult result =
      run("simulate c.curvefold.json --percent 0:100:5 --steps 300 --gif c.gif");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_NE(result.out.find("wrote c.gif"), std::string::npos) << result.out;
  const DecodedGif gif = decodeGif(path("c.gif"));
  ASSERT_EQ(gif.frames.size(), 5u);
  EXPECT_EQ(gif.width, 640);
  EXPECT_EQ(gif.height, 360);
  EXPECT_TRUE(gif.loops);
  EXPECT_EQ(gif.delays, (std::vector<int>{10, 10, 10, 10, 100}));
  for (std::size_t i = 0; i < gif.frames.size(); ++i)
    for (std::size_t j = i + 1; j < gif.frames.size(); ++j)
      EXPECT_GT(changedShare(gif.frames[i], gif.frames[j]), 0.002)
          << "frames " << i << " and " << j << " show the same state";
  // The flat sheet and the folded cone cover different pixels (the camera holds still).
  EXPECT_GT(changedShare(gif.frames.front(), gif.frames.back()), 0.02);
}

// Each frame of --frames shows its own state: the last frame is the same picture as --png of the
// same (last) state.
TEST_F(SimulateCli, EveryFramePictureShowsItsOwnState) {
  ASSERT_EQ(run("new cone --resolution 12 -o c.curvefold.json").exitCode, 0);
  const CommandResult result =
      run("simulate c.curvefold.json --percent 0:100:3 --settle --frames f --png last.png");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::string last = slurp(path("last.png"));
  ASSERT_FALSE(last.empty());
  EXPECT_TRUE(slurp(path("f/frame_0002.png")) == last);
  EXPECT_FALSE(slurp(path("f/frame_0001.png")) == last);
}

// --gif: one line and exit 1 for a single state, the input, a folder or a missing folder; nothing
// written, and an existing GIF is left as it was when another output fails.
TEST_F(SimulateCli, BadGifOutputsAreOneLineAndWriteNothing) {
  ASSERT_EQ(run("new square -o s.curvefold.json").exitCode, 0);
  fs::create_directory(path("folder"));
  for (const auto& [options, fragment] : std::vector<std::pair<std::string, std::string>>{
           {"--percent 50 --gif s.gif", "--gif"},
           {"--percent 0:100:3 --gif s.curvefold.json", "s.curvefold.json"},
           {"--percent 0:100:3 --gif folder", "folder"},
           {"--percent 0:100:3 --gif missing/s.gif", "missing"},
           {"--percent 0:100:3 --gif s.gif --obj missing/s.obj", "missing"}}) {
    const CommandResult result = run("simulate s.curvefold.json --steps 10 " + options);
    EXPECT_EQ(result.exitCode, 1) << options;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1)
        << options << ": " << result.err;
    EXPECT_NE(result.err.find(fragment), std::string::npos) << options << ": " << result.err;
    EXPECT_FALSE(fs::exists(path("s.gif"))) << options;
    EXPECT_FALSE(fs::exists(path("missing"))) << options;
  }
  { std::ofstream(path("old.gif")) << "before"; }
  const CommandResult failed = run(
      "simulate s.curvefold.json --steps 10 --percent 0:100:3 --gif old.gif --obj missing/x.obj");
  EXPECT_EQ(failed.exitCode, 1);
  EXPECT_EQ(slurp(path("old.gif")), "before");
  for (const auto& entry : fs::directory_iterator(dir_))
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
}

}  // namespace
}  // namespace curvefold::testing
