// The studio panel (issue 14, 1), headless: Dear ImGui runs without a renderer, the test clicks
// items by their label (where the panel says it drew them) and checks what the panel asked of its
// host or wrote. The same panel serves the desktop window and the headset.
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <imgui.h>

#include "app/session/cover_facts.hpp"
#include "app/session/document.hpp"
#include "app/studio/headset_studio.hpp"
#include "app/studio/studio_panel.hpp"
#include "app/studio/studio_target.hpp"
#include "app/studio/zenity_picker.hpp"
#include "engine/io/design_document.hpp"
#include "engine/text/utf8.hpp"
#include "test_paths.hpp"

namespace curvefold::studio {
namespace {

namespace fs = std::filesystem;

extern "C" char** environ;

// Sets (or, given null, unsets) an environment variable for its lifetime.
class ScopedEnv {
 public:
  ScopedEnv(std::string name, const char* value) : name_(std::move(name)) {
    if (const char* old = std::getenv(name_.c_str())) old_ = old;
    set(value);
  }
  ~ScopedEnv() { set(old_ ? old_->c_str() : nullptr); }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;
  void set(const char* value) {
    if (value)
      ::setenv(name_.c_str(), value, 1);
    else
      ::unsetenv(name_.c_str());
  }

 private:
  std::string name_;
  std::optional<std::string> old_;
};

// Starts `arguments` with its standard output on a pipe (and its standard error in `errors` when
// given): the child and the pipe's read end.
std::pair<pid_t, int> spawnReading(std::vector<std::string> arguments,
                                   const std::string& errors = "") {
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  int output[2];
  if (::pipe2(output, O_CLOEXEC) != 0) return {-1, -1};
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_adddup2(&files, output[1], 1);
  if (!errors.empty())
    posix_spawn_file_actions_addopen(&files, 2, errors.c_str(), O_WRONLY | O_CREAT | O_APPEND,
                                     0644);
  pid_t child = -1;
  if (::posix_spawn(&child, argv[0], &files, nullptr, argv.data(), environ) != 0) child = -1;
  posix_spawn_file_actions_destroy(&files);
  ::close(output[1]);
  return {child, output[0]};
}

// One line from `fd`, without its newline; empty when none came within five seconds.
std::string readLine(int fd) {
  std::string line;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (std::chrono::steady_clock::now() < deadline) {
    pollfd ready = {fd, POLLIN, 0};
    if (::poll(&ready, 1, 100) <= 0) continue;
    char c = 0;
    if (::read(fd, &c, 1) != 1) break;
    if (c == '\n') return line;
    line += c;
  }
  return "";
}

// A private session bus (dbus-daemon with the policy of Debian's session.conf, nothing
// activatable on it) in DBUS_SESSION_BUS_ADDRESS,
// and, once `startPortal()`, the fake portal (tests/fake_portal.cpp) on it.
class PortalBus {
 public:
  explicit PortalBus(const fs::path& dir) : dir_(dir) {
    const fs::path config = dir_ / "bus.conf";
    std::ofstream(config) << "<busconfig><type>session</type>"
                          << "<listen>unix:tmpdir=" << dir_.string() << "</listen>"
                          << "<auth>EXTERNAL</auth><policy context=\"default\">"
                          << "<allow send_destination=\"*\" eavesdrop=\"true\"/>"
                          << "<allow eavesdrop=\"true\"/><allow own=\"*\"/></policy>"
                          << "</busconfig>\n";
    std::tie(daemon_, daemonOut_) = spawnReading(
        {"/usr/bin/dbus-daemon", "--config-file=" + config.string(), "--nofork", "--nopidfile",
         "--print-address=1"},
        (dir_ / "bus.log").string());  // as root it says it cannot raise its descriptor limit
    address_ = readLine(daemonOut_);
    if (!address_.empty()) ::setenv("DBUS_SESSION_BUS_ADDRESS", address_.c_str(), 1);
  }
  ~PortalBus() {
    for (const pid_t child : {portal_, daemon_}) {
      if (child <= 0) continue;
      ::kill(child, SIGKILL);  // the fake first: it never sees its bus go
      ::waitpid(child, nullptr, 0);
    }
    for (const int out : {portalOut_, daemonOut_})
      if (out >= 0) ::close(out);
  }
  bool up() const { return !address_.empty(); }
  // The fake portal owns its name on the bus; false when it did not say so.
  bool startPortal() {
    answer("never");
    std::tie(portal_, portalOut_) = spawnReading(
        {CURVEFOLD_FAKE_PORTAL, (dir_ / "answer").string(), (dir_ / "portal.log").string()});
    return readLine(portalOut_) == "ready";
  }
  // How the portal answers the next dialog: "uri <URI>", "cancel", "fail", "nothing" or "never".
  void answer(const std::string& how) { std::ofstream(dir_ / "answer") << how << "\n"; }
  std::string log() const {
    std::stringstream text;
    text << std::ifstream(dir_ / "portal.log").rdbuf();
    return text.str();
  }

 private:
  fs::path dir_;
  pid_t daemon_ = -1, portal_ = -1;
  int daemonOut_ = -1, portalOut_ = -1;
  std::string address_;
};

class StudioPanelTest : public ::testing::Test {
 protected:
  StudioPanelTest() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(900, 700);
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);  // the atlas a frame needs
    dir_ = fs::path(::testing::TempDir()) / ("panel-" + std::to_string(getpid()));
    fs::create_directories(dir_);
    doc_ = session::makeDocument(Design{GeneratedSurface{"square", {{"resolution", 8}}}, {}},
                                 "square");
    actions_.replaceDocument = [this](const Design& design, const std::string& name) {
      replaced_.push_back(name);
      doc_ = session::makeDocument(design, name);
    };
    actions_.press = [this](Button button) { pressed_.push_back(button); };
    actions_.exportPng = [](const std::string&) { throw std::runtime_error("no renderer here"); };
  }
  ~StudioPanelTest() override {
    ImGui::DestroyContext();
    fs::remove_all(dir_);
  }

  void frame() {
    ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
    ImGui::NewFrame();
    panel_.draw(doc_, actions_, stats_, creasePattern_);
    ImGui::Render();
  }
  // Press and release the mouse on the item with this label, as a hand's ray would.
  void click(const std::string& label) {
    frame();
    const std::optional<glm::vec2> at = panel_.itemCentre(label);
    ASSERT_TRUE(at) << "no item \"" << label << "\"";
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(at->x, at->y);
    frame();
    io.MouseDown[0] = true;
    frame();
    io.MouseDown[0] = false;
    frame();
  }

  // Frames until `done` holds (a worker's result), at most 10 s.
  bool framesUntil(const std::function<bool()>& done) {
    for (int i = 0; i < 1000 && !done(); ++i) {
      frame();
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return done();
  }
  // Lays the panel out as `before` leaves it and as `after` does, filling the display and not, and
  // expects every item of a panel with a target and suggestions where it was: a recorded
  // session's pointing (positions, not labels) lands on the same items.
  void expectItemsStay(const std::function<void()>& before, const std::function<void()>& after) {
    actions_.loadTarget = [](const std::string&) {};
    actions_.suggest = [] {};
    const std::vector<std::string> labels = {
        "surface", "Create", "Undo",        "crease pattern", "save as", "Save",
        "open",    "Open",   "export to",   "FOLD",           "SVG",     "PNG",
        "PDF",     "target", "Load target", "Suggest",        "Take",    "Recent designs"};
    auto centres = [&](const std::function<void()>& change) {
      change();
      frame();
      frame();
      std::vector<glm::vec2> at;
      for (const std::string& label : labels) {
        const std::optional<glm::vec2> centre = panel_.itemCentre(label);
        EXPECT_TRUE(centre) << "no item \"" << label << "\"";
        at.push_back(centre.value_or(glm::vec2(-1.0f)));
      }
      return at;
    };
    for (const bool fills : {false, true}) {
      panel_.setFillsDisplay(fills);
      const std::vector<glm::vec2> first = centres(before), second = centres(after);
      for (std::size_t i = 0; i < labels.size(); ++i)
        EXPECT_EQ(first[i], second[i]) << labels[i] << (fills ? " (fills the display)" : "");
    }
  }
  // A zenity on PATH that runs `body` (sh), for the panel's Browse; PATH is restored after.
  void fakeZenity(const std::string& body) {
    const fs::path bin = dir_ / "bin";
    fs::create_directories(bin);
    std::ofstream(bin / "zenity") << "#!/bin/sh\n" << body << "\n";
    fs::permissions(bin / "zenity", fs::perms::owner_all);
    setPath(bin.string() + ":" + oldPath_);
  }
  void setPath(const std::string& path) { ::setenv("PATH", path.c_str(), 1); }
  std::string slurp(const fs::path& path) {
    std::stringstream text;
    text << std::ifstream(path).rdbuf();
    return text.str();
  }

  const std::string oldPath_ = std::getenv("PATH") ? std::getenv("PATH") : "";
  struct RestorePath {
    std::string path;
    ~RestorePath() { ::setenv("PATH", path.c_str(), 1); }
  } restorePath_{oldPath_};
  // No session bus unless a test starts one: a desktop's own portal would answer Browse.
  ScopedEnv noBus_{"DBUS_SESSION_BUS_ADDRESS", nullptr}, noRuntimeDir_{"XDG_RUNTIME_DIR", nullptr};
  fs::path dir_;
  session::Document doc_;
  StudioActions actions_;
  StudioStats stats_;
  bool creasePattern_ = false;
  StudioPanel panel_{false, "help"};
  std::vector<std::string> replaced_;
  std::vector<Button> pressed_;
};

TEST_F(StudioPanelTest, ButtonsAskTheHostByLabel) {
  click("Undo");
  click("Redo");
  click("Cancel");
  click("Switch hands");
  EXPECT_EQ(pressed_,
            (std::vector<Button>{Button::Undo, Button::Redo, Button::Cancel, Button::SwitchHands}));
  click("crease pattern");
  EXPECT_TRUE(creasePattern_);
  EXPECT_FALSE(panel_.itemCentre("no such item"));
}

TEST_F(StudioPanelTest, CreateMakesANewSheetFromTheCatalog) {
  click("Create");
  ASSERT_EQ(replaced_.size(), 1u);
  EXPECT_EQ(replaced_[0], "square");  // the catalog's first surface, at its defaults
  EXPECT_EQ(panel_.message(), "new square");
}

TEST_F(StudioPanelTest, ExportsWriteBesideTheExportBaseAndFailuresAreShown) {
  const std::string base = (dir_ / "made").string();
  StudioPanel panel(false, "help", base);
  panel_ = std::move(panel);
  click("SVG");
  EXPECT_TRUE(fs::exists(base + ".svg")) << panel_.message();
  click("FOLD");
  EXPECT_TRUE(fs::exists(base + ".fold")) << panel_.message();
  EXPECT_EQ(panel_.message(), "wrote " + base + ".fold");
  click("PNG");  // the host cannot: its message is shown, nothing is written
  EXPECT_EQ(panel_.message(), "no renderer here");
  EXPECT_FALSE(fs::exists(base + ".png"));
  // The PDF to print, with the host's picture of the folded form on its cover.
  int pictures = 0;
  actions_.foldedForm = [&pictures]() -> std::optional<PdfPicture> {
    ++pictures;
    return PdfPicture{2, 2, std::vector<std::uint8_t>(16, 128)};
  };
  click("PDF");
  EXPECT_EQ(panel_.message(), "wrote " + base + ".pdf");
  EXPECT_EQ(pictures, 1);
  ASSERT_TRUE(fs::exists(base + ".pdf"));
  EXPECT_GT(fs::file_size(base + ".pdf"), 1000u);
}

// A PDF's bytes without the creation time Cairo writes into it.
std::string undated(const std::string& pdf) {
  static const std::regex kCreationDate(R"(/CreationDate \(D:[0-9Z+'-]*\))");
  return std::regex_replace(pdf, kCreationDate, "");
}

// Issue 41: the studio's PDF carries the cover the command line's `export --pdf` and Python's
// print (session::coverFacts: surface, folds and the date), not a list of its own without the
// date; the host's picture is the folded form.
TEST_F(StudioPanelTest, ThePdfCoverHasTheCommandLinesFactsAndTheDate) {
  const std::string base = (dir_ / "made").string();
  panel_.setExportBase(base);
  const PdfPicture picture{2, 2, std::vector<std::uint8_t>(16, 128)};
  actions_.foldedForm = [&picture]() -> std::optional<PdfPicture> { return picture; };
  click("PDF");
  ASSERT_EQ(panel_.message(), "wrote " + base + ".pdf");

  PdfOptions print;  // what `curvefold export made.curvefold.json --pdf` prints
  print.title = "made";
  print.facts = session::coverFacts(doc_.design());
  print.picture = picture;
  writeCreasePatternPdf(doc_.session->fixed(), (dir_ / "expected.pdf").string(), print);
  EXPECT_EQ(undated(slurp(base + ".pdf")), undated(slurp(dir_ / "expected.pdf")));
}

// The cover's facts end with today's local date, read here apart from session::today().
TEST(StudioCoverFacts, SaySurfaceSymmetryFoldsAndTodaysDate) {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char date[32];
  std::snprintf(date, sizeof date, "%04d-%02d-%02d", local.tm_year + 1900, local.tm_mon + 1,
                local.tm_mday);
  Design design{GeneratedSurface{"cylinder", {}}, {}};
  design.symmetry = "mirror:x";
  const std::vector<std::string> facts = session::coverFacts(design);
  ASSERT_EQ(facts.size(), 3u);
  EXPECT_EQ(facts[0], "surface: cylinder, mirror:x");
  EXPECT_EQ(facts[1], "folds: 0");
  EXPECT_EQ(facts[2], std::string("date: ") + date);
}

// Issue 29, 3: paths are kept whole (a 512-byte buffer cut a 600-character export path and the
// files landed under a truncated name).
TEST_F(StudioPanelTest, ALongExportPathIsKeptWhole) {
  fs::path folder = dir_;
  for (int i = 0; i < 6; ++i) folder /= std::string(100, char('a' + i));
  fs::create_directories(folder);
  const std::string base = (folder / "made").string();
  ASSERT_GT(base.size(), 600u);
  panel_.setExportBase(base);
  click("SVG");
  EXPECT_EQ(panel_.message(), "wrote " + base + ".svg");
  EXPECT_TRUE(fs::exists(base + ".svg"));
}

// Issue 29, 3: the recent list holds only what a recording can (UTF-8: a recording is JSON, and a
// path that is not stopped `xr --record`), and an entry that is not a regular file (a FIFO, from
// another machine's recording) is refused, not opened: the open would block.
TEST_F(StudioPanelTest, TheRecentListHoldsUtf8AndOpensOnlyFiles) {
  const std::string fifo = (dir_ / "pipe.curvefold.json").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  panel_.setRecent({fifo, "/x/\xff\xfe.curvefold.json", "/x/caf\xc3\xa9.curvefold.json"});
  EXPECT_EQ(panel_.recent(), (std::vector<std::string>{fifo, "/x/caf\xc3\xa9.curvefold.json"}));
  click("Recent designs");
  click("pipe.curvefold.json");
  EXPECT_TRUE(replaced_.empty());
  EXPECT_EQ(panel_.message(),
            "cannot open " + fifo + ": it is a FIFO (named pipe), not a regular file");
}

// The symmetry list holds what the chosen surface has (the square: its mirrors and quarter
// turns, issue 28, 2), and a new sheet takes the one chosen.
TEST_F(StudioPanelTest, TheSymmetryListHoldsTheSurfacesOwn) {
  click("symmetry");
  EXPECT_TRUE(panel_.itemCentre("none"));
  EXPECT_TRUE(panel_.itemCentre("rotational:4:z"));
  EXPECT_FALSE(panel_.itemCentre("rotational:12:y"));  // the cylinder's, not the square's
  click("none");
  click("surface");
  click("cylinder");
  click("symmetry");
  EXPECT_TRUE(panel_.itemCentre("rotational:12:y"));
  click("mirror:y");
  click("Create");
  ASSERT_EQ(replaced_.size(), 1u);
  EXPECT_EQ(panel_.message(), "new cylinder, mirror:y");
}

TEST_F(StudioPanelTest, ARecordedSessionOffersNoNewSheetOrOpen) {
  StudioPanel recording(true, "help");
  panel_ = std::move(recording);
  frame();
  EXPECT_FALSE(panel_.itemCentre("Create"));
  EXPECT_FALSE(panel_.itemCentre("Open"));
  EXPECT_TRUE(panel_.itemCentre("Save"));
}

// Saving puts the design at the top of the recent list (the host keeps it); the list opens it
// again, by its file name; a replay's host (writeFile set) writes nothing.
TEST_F(StudioPanelTest, SavedDesignsAreRecentAndOpenFromTheList) {
  std::vector<std::vector<std::string>> kept;
  actions_.recentChanged = [&kept](const std::vector<std::string>& recent) {
    kept.push_back(recent);
  };
  const std::string saved = (dir_ / "bowl.curvefold.json").string();
  panel_.setSavePath(saved);
  panel_.setRecent({"/elsewhere/old.curvefold.json"});
  click("Save");
  ASSERT_TRUE(fs::exists(saved)) << panel_.message();
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0], (std::vector<std::string>{saved, "/elsewhere/old.curvefold.json"}));
  EXPECT_EQ(panel_.recent(), kept[0]);
  click("Recent designs");
  click("bowl.curvefold.json");
  ASSERT_EQ(replaced_.size(), 1u);
  EXPECT_EQ(replaced_[0], saved);
  EXPECT_EQ(panel_.message(), "opened " + saved);

  std::vector<std::string> asked;
  actions_.writeFile = [&asked](const std::string& path,
                                const std::function<void(const std::string&)>&) {
    asked.push_back(path);
  };
  fs::remove(saved);
  click("Save");
  EXPECT_EQ(asked, (std::vector<std::string>{saved}));
  EXPECT_FALSE(fs::exists(saved));
}

// The panel's items are where they are whatever the machine's recent list holds: a recorded
// session's pointing (positions, not labels) replays onto the same items on another machine. The
// list opening is the user's doing and recorded; what it holds is not.
TEST_F(StudioPanelTest, ItemsStayWhereTheyAreWhateverTheRecentListHolds) {
  expectItemsStay([&] { panel_.setRecent({}); },
                  [&] {
                    panel_.setRecent({"/a/one.curvefold.json", "/b/two.curvefold.json",
                                      "/c/three.curvefold.json"});
                  });
}

}  // namespace
}  // namespace curvefold::studio

namespace curvefold::studio {
namespace {

// Issue 31, 1: Save and the exports follow the design's name: an opened design saves to its own
// file and exports beside it; a new sheet is named after its surface.
TEST_F(StudioPanelTest, SaveAndExportsFollowTheOpenedDesignsName) {
  EXPECT_EQ(panel_.savePath(), "design.curvefold.json");  // a host that names nothing
  const std::string vase = (dir_ / "vase.curvefold.json").string();
  saveDesign(doc_.design(), vase);
  panel_.setRecent({vase});
  click("Recent designs");
  click("vase.curvefold.json");
  ASSERT_EQ(panel_.message(), "opened " + vase);
  EXPECT_EQ(panel_.savePath(), vase);
  EXPECT_EQ(panel_.exportBase(), (dir_ / "vase").string());
  click("SVG");
  EXPECT_EQ(panel_.message(), "wrote " + (dir_ / "vase.svg").string());
  EXPECT_TRUE(fs::exists(dir_ / "vase.svg"));
  click("Create");
  EXPECT_EQ(panel_.savePath(), "square.curvefold.json");
  EXPECT_EQ(panel_.exportBase(), "square");
  // A host names the design it starts with: an autosave's design is named without ".autosave".
  panel_.nameDesign("designs/bowl.autosave.curvefold.json");
  EXPECT_EQ(panel_.savePath(), "designs/bowl.curvefold.json");
  panel_.setFilesDir("exports");  // the headset's: everything in one folder
  panel_.nameDesign("designs/bowl.json");
  EXPECT_EQ(panel_.savePath(), "exports/bowl.curvefold.json");
  EXPECT_EQ(panel_.exportBase(), "exports/bowl");
}

// Issue 31, 1: on the desktop the recent designs are offered beside Open.
TEST_F(StudioPanelTest, TheDesktopOffersRecentDesignsBesideOpen) {
  const std::string vase = (dir_ / "vase.curvefold.json").string();
  saveDesign(doc_.design(), vase);
  panel_.setRecent({vase});
  frame();
  EXPECT_FALSE(panel_.itemCentre("Recent"));  // the headset's panel: not there
  panel_.setDesktop(true);
  click("Recent");
  click("vase.curvefold.json");
  ASSERT_EQ(replaced_, (std::vector<std::string>{vase}));
  EXPECT_EQ(panel_.savePath(), vase);
}

// Issue 31, 1: with zenity on PATH, Browse... opens it without holding a frame, and the chosen path
// fills the field (Open's, or Save's with --save).
TEST_F(StudioPanelTest, BrowseFillsTheFieldFromZenity) {
  fakeZenity(
      "printf '%s\\n' \"$@\" > \"$(dirname \"$0\")/args\"\necho /chosen/bowl.curvefold.json");
  panel_.setDesktop(true);
  click("Browse...##open");
  ASSERT_TRUE(framesUntil([&] { return panel_.openPath() == "/chosen/bowl.curvefold.json"; }))
      << panel_.message();
  std::string args = slurp(dir_ / "bin" / "args");
  EXPECT_NE(args.find("--file-selection\n"), std::string::npos) << args;
  EXPECT_EQ(args.find("--save"), std::string::npos) << args;
  click("Browse...##save");
  ASSERT_TRUE(framesUntil([&] { return panel_.savePath() == "/chosen/bowl.curvefold.json"; }))
      << panel_.message();
  args = slurp(dir_ / "bin" / "args");
  EXPECT_NE(args.find("--save\n"), std::string::npos) << args;
  EXPECT_NE(args.find("--filename=design.curvefold.json\n"), std::string::npos) << args;
  // Cancelled (zenity exits 1): the field keeps its path.
  fakeZenity("exit 1");
  click("Browse...##open");
  ASSERT_TRUE(framesUntil([&] { return panel_.message() == "no file chosen"; }))
      << panel_.message();
  EXPECT_EQ(panel_.openPath(), "/chosen/bowl.curvefold.json");
}

// Issue 40, 4: waiting on zenity that fails (poll() refused: here the descriptors it watches exceed
// RLIMIT_NOFILE, lowered while the dialog is open) was taken for "no file chosen"; it is said.
TEST_F(StudioPanelTest, AFailedWaitForTheFilePickerIsSaid) {
  fakeZenity(
      "echo $$ > \"$(dirname \"$0\")/pid\"\ntrap 'echo /chosen/x.curvefold.json; exit 0' USR1\n"
      "while :; do sleep 0.05; done");
  studio::ZenityPicker picker(studio::ZenityPicker::find());
  picker.start(false, "");
  const fs::path pidFile = dir_ / "bin" / "pid";
  const auto start = std::chrono::steady_clock::now();
  while (slurp(pidFile).empty() &&
         std::chrono::steady_clock::now() - start < std::chrono::seconds(20))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const pid_t pid = std::stoi(slurp(pidFile));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the worker waits in poll()
  rlimit old{};
  ASSERT_EQ(::getrlimit(RLIMIT_NOFILE, &old), 0);
  const rlimit low{1, old.rlim_max};
  ASSERT_EQ(::setrlimit(RLIMIT_NOFILE, &low), 0);
  ::kill(pid, SIGUSR1);  // the path comes, and the next wait fails
  std::optional<studio::FilePicker::Picked> picked;
  while (!(picked = picker.poll()) &&
         std::chrono::steady_clock::now() - start < std::chrono::seconds(20))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ::setrlimit(RLIMIT_NOFILE, &old);
  ASSERT_TRUE(picked);
  EXPECT_EQ(picked->path, "");
  EXPECT_EQ(picked->error,
            "cannot wait for the file picker (zenity): Invalid argument; type the path instead");
}

// The symmetry list says why it offers none (issue 40, 4): a star whose notches lie beyond its
// points (the inner radius's slider clicked in its middle, 5 km) is refused, and the list says so
// where it showed "none" alone.
TEST_F(StudioPanelTest, TheSymmetryListSaysWhyItOffersNone) {
  click("surface");
  click("star");
  click("inner_radius");
  click("symmetry");
  EXPECT_TRUE(panel_.itemCentre("none"));
  EXPECT_TRUE(panel_.itemCentre("no symmetries")) << panel_.message();
  EXPECT_EQ(panel_.message().rfind("no symmetries: surface 'star': parameter 'inner_radius' = ", 0),
            0u)
      << panel_.message();
}

// Frames go on while the dialog is open, and closing the panel ends the dialog at once.
TEST_F(StudioPanelTest, AnOpenDialogHoldsNoFrameAndEndsWithThePanel) {
  fakeZenity("echo $$ > \"$(dirname \"$0\")/pid\"\nexec sleep 30");
  panel_.setDesktop(true);
  const auto start = std::chrono::steady_clock::now();
  click("Browse...##open");
  const fs::path pidFile = dir_ / "bin" / "pid";
  ASSERT_TRUE(framesUntil([&] { return !slurp(pidFile).empty(); }));
  for (int i = 0; i < 20; ++i) frame();
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(3));
  EXPECT_EQ(panel_.message(), "choosing a file to open");
  const pid_t pid = std::stoi(slurp(pidFile));
  EXPECT_EQ(::kill(pid, 0), 0);
  panel_ = StudioPanel(false, "help");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(6));
  EXPECT_EQ(::kill(pid, 0), -1);  // ended and reaped
  EXPECT_EQ(errno, ESRCH);
}

// Issue 31, 1: where the session bus has the desktop portal, Browse... asks its FileChooser (not
// zenity, though it is on PATH), with the designs' filters and where to start; the chosen file's
// path fills the field, a cancel keeps it, and a file that is not on this machine is refused.
TEST_F(StudioPanelTest, BrowseAsksTheDesktopPortalWhereTheSessionHasOne) {
  fakeZenity("touch \"$(dirname \"$0\")/ran\"\nexit 1");
  PortalBus bus(dir_);
  ASSERT_TRUE(bus.up());
  ASSERT_TRUE(bus.startPortal());
  panel_.setDesktop(true);
  bus.answer("uri file:///chosen/bowl.curvefold.json");
  click("Browse...##open");
  ASSERT_TRUE(framesUntil([&] { return panel_.openPath() == "/chosen/bowl.curvefold.json"; }))
      << panel_.message() << "\n"
      << bus.log();
  EXPECT_NE(bus.log().find("OpenFile title=Open a design token=curvefold"), std::string::npos)
      << bus.log();
  EXPECT_NE(bus.log().find("filters=a(sa(us))"), std::string::npos) << bus.log();

  bus.answer("uri file:///chosen/cup%20one.curvefold.json");
  click("Browse...##save");
  ASSERT_TRUE(framesUntil([&] { return panel_.savePath() == "/chosen/cup one.curvefold.json"; }))
      << panel_.message() << "\n"
      << bus.log();
  EXPECT_NE(bus.log().find("SaveFile title=Save the design as"), std::string::npos) << bus.log();
  EXPECT_NE(bus.log().find("current_folder=" + fs::current_path().string() +
                           " current_name=design.curvefold.json"),
            std::string::npos)
      << bus.log();

  bus.answer("cancel");
  click("Browse...##open");
  ASSERT_TRUE(framesUntil([&] { return panel_.message() == "no file chosen"; }))
      << panel_.message();
  EXPECT_EQ(panel_.openPath(), "/chosen/bowl.curvefold.json");

  bus.answer("uri https://example.com/bowl.curvefold.json");
  click("Browse...##open");
  ASSERT_TRUE(framesUntil([&] {
    return panel_.message().find("not on this machine") != std::string::npos;
  })) << panel_.message();
  EXPECT_EQ(panel_.openPath(), "/chosen/bowl.curvefold.json");
  EXPECT_FALSE(fs::exists(dir_ / "bin" / "ran"));
}

// Frames go on while the portal's dialog is open, and closing the panel closes the dialog's
// Request (the portal takes the dialog down) without waiting for a person.
TEST_F(StudioPanelTest, ClosingThePanelClosesThePortalsDialog) {
  PortalBus bus(dir_);
  ASSERT_TRUE(bus.up());
  ASSERT_TRUE(bus.startPortal());
  panel_.setDesktop(true);
  const auto start = std::chrono::steady_clock::now();
  click("Browse...##open");
  ASSERT_TRUE(framesUntil([&] { return bus.log().find("OpenFile") != std::string::npos; }));
  for (int i = 0; i < 20; ++i) frame();
  EXPECT_EQ(panel_.message(), "choosing a file to open");
  EXPECT_EQ(bus.log().find("Close"), std::string::npos);
  panel_ = StudioPanel(false, "help");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  const std::string log = bus.log();
  const std::size_t token = log.find("token=");
  ASSERT_NE(token, std::string::npos) << log;
  const std::string name = log.substr(token + 6, log.find(' ', token) - token - 6);
  EXPECT_NE(log.find("Close /org/freedesktop/portal/desktop/request/"), std::string::npos) << log;
  EXPECT_NE(log.find("/" + name + "\n"), std::string::npos) << log;
}

// A portal that ends the dialog some other way, or answers success with no file, is said in one
// line on the panel, and the field keeps its path.
TEST_F(StudioPanelTest, APortalThatGivesNoFileIsSaidInOneLine) {
  PortalBus bus(dir_);
  ASSERT_TRUE(bus.up());
  ASSERT_TRUE(bus.startPortal());
  panel_.setDesktop(true);
  const std::string before = panel_.openPath();
  for (const char* how : {"fail", "nothing"}) {
    SCOPED_TRACE(how);
    bus.answer(how);
    click("Browse...##open");
    ASSERT_TRUE(framesUntil([&] { return panel_.message().rfind("the desktop portal ", 0) == 0; }))
        << panel_.message();
    EXPECT_EQ(panel_.message().find('\n'), std::string::npos);
    EXPECT_NE(panel_.message().find("type the path instead"), std::string::npos);
    EXPECT_EQ(panel_.openPath(), before);
  }
}

// A session bus that is not there (a stale DBUS_SESSION_BUS_ADDRESS) leaves Browse to zenity at
// once.
TEST_F(StudioPanelTest, AStaleBusAddressLeavesBrowseToZenity) {
  fakeZenity("echo /chosen/by-zenity.curvefold.json");
  ::setenv("DBUS_SESSION_BUS_ADDRESS", ("unix:path=" + (dir_ / "no-bus").string()).c_str(), 1);
  const auto start = std::chrono::steady_clock::now();
  panel_.setDesktop(true);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
  click("Browse...##open");
  ASSERT_TRUE(framesUntil([&] { return panel_.openPath() == "/chosen/by-zenity.curvefold.json"; }))
      << panel_.message();
}

// A session bus without the portal leaves Browse to zenity.
TEST_F(StudioPanelTest, ABusWithoutThePortalLeavesBrowseToZenity) {
  fakeZenity("echo /chosen/by-zenity.curvefold.json");
  PortalBus bus(dir_);
  ASSERT_TRUE(bus.up());
  panel_.setDesktop(true);
  click("Browse...##open");
  ASSERT_TRUE(framesUntil([&] { return panel_.openPath() == "/chosen/by-zenity.curvefold.json"; }))
      << panel_.message();
}

// Without zenity the path fields are all there is; the desktop's items never move the others.
TEST_F(StudioPanelTest, DesktopItemsMoveNothingElse) {
  setPath((dir_ / "nothing here").string());
  panel_.setDesktop(true);
  frame();
  EXPECT_FALSE(panel_.itemCentre("Browse...##open"));
  EXPECT_TRUE(panel_.itemCentre("open"));
  fakeZenity("exit 1");
  for (const bool desktop : {false, true}) {
    panel_.setDesktop(desktop);
    frame();
    EXPECT_EQ(bool(panel_.itemCentre("Browse...##open")), desktop);
    EXPECT_EQ(bool(panel_.itemCentre("Browse...##save")), desktop);
  }
  expectItemsStay([&] { panel_.setDesktop(false); }, [&] { panel_.setDesktop(true); });
}

// The headset has no desktop picker, even where zenity is installed; its files go to its folder.
TEST_F(StudioPanelTest, TheHeadsetKeepsItsPathFields) {
  fakeZenity("exit 1");
  HeadsetStudioOptions options;
  options.exportDir = "exports";
  options.name = (dir_ / "vase.curvefold.json").string();
  HeadsetStudio studio(doc_, options);
  InputFrame frame;
  frame.sheetHand.tracked = true;
  studio.process(frame);
  EXPECT_TRUE(studio.panel().itemCentre("open"));
  EXPECT_FALSE(studio.panel().itemCentre("Browse...##open"));
  EXPECT_FALSE(studio.panel().itemCentre("Recent"));
  EXPECT_EQ(studio.panel().savePath(), "exports/vase.curvefold.json");
}

// Issue 38, 4: every line of the panel readable at its width, the desktop's floating panel (300
// pixels) and the headset's (480): the target's distance and suggestion lines, as long as they
// come, wrap instead of running past the edge ("Chamfer 24.4 m" for "Chamfer 24.4 mm (12.2%)").
// A glyph past its clip rectangle is text cut off. ImGui leaves out the glyphs wholly past it, so
// a line cut where a space meets the edge shows no such glyph: each panel is also tried a few
// pixels wider (the desktop's panel can be widened), so that some cut falls inside a letter.
TEST_F(StudioPanelTest, EveryLineIsWholeAtThePanelsWidth) {
  actions_.loadTarget = [](const std::string&) {};
  actions_.suggest = [] {};
  ImGui::GetStyle().AntiAliasedLinesUseTex = false;  // lines too sample only the white pixel
  const std::vector<std::pair<std::string, std::string>> lines = {
      {"(measuring) " + distanceText(0.0244, 0.0244, 0.2001),
       "suggestion 1 of 3: Chamfer 0.345 mm -> 0.000752 mm"},
      {"/home/designer/targets/lampshade with a bulge.obj: the target is 1e+03 times the sheet's "
       "size (212 m across against 0.212 m): are its units metres?",
       "the design changed while searching: suggest again"},
      {"loading the target /home/designer/targets/a rather long folder name/vase.obj ...",
       "searching for the next fold ..."}};
  for (const bool fills : {false, true})
    for (const float wider : {0.0f, 4.0f, 9.0f}) {
      const float width = (fills ? 480.0f : 300.0f) + wider;
      ImGui::GetIO().DisplaySize = fills ? ImVec2(width, 600) : ImVec2(1280, 720);
      panel_.setFillsDisplay(fills);
      for (const auto& [target, suggestion] : lines) {
        stats_.targetLine = target;
        stats_.suggestionLine = suggestion;
        frame();
        if (!fills) ImGui::SetWindowSize("curvefold", ImVec2(width, 0.0f));
        frame();
        frame();
        const ImDrawData* data = ImGui::GetDrawData();
        ASSERT_NE(data, nullptr);
        std::size_t cut = 0;
        const ImVec2 white = ImGui::GetIO().Fonts->TexUvWhitePixel;
        for (int l = 0; l < data->CmdListsCount; ++l) {
          const ImDrawList* list = data->CmdLists[l];
          for (const ImDrawCmd& cmd : list->CmdBuffer)
            for (unsigned i = 0; i < cmd.ElemCount; ++i) {
              const ImDrawVert& v =
                  list->VtxBuffer[list->IdxBuffer[cmd.IdxOffset + i] + cmd.VtxOffset];
              // Glyphs only: shapes (a border on the display's edge) sample the white pixel.
              if (v.uv.x == white.x && v.uv.y == white.y) continue;
              const ImVec2 p = v.pos;
              const bool outside = p.x > cmd.ClipRect.z + 1.0f || p.x < cmd.ClipRect.x - 1.0f;
              if (outside && cut == 0)
                ADD_FAILURE() << "at " << p.x << ", " << p.y << " outside " << cmd.ClipRect.x
                              << ".." << cmd.ClipRect.z << " (list " << l << ")";
              cut += outside;
            }
        }
        EXPECT_EQ(cut, 0u) << "cut at the panel's width " << width
                           << (fills ? " (headset)" : " (desktop)") << ": " << target << " / "
                           << suggestion;
      }
    }
}

// Issue 38, 4: ImGui's own wrap also breaks after a '.', and the desktop's panel showed
// "Chamfer 0." on one row and "474 mm" on the next. The target's lines break at spaces only, each
// row within the width.
TEST_F(StudioPanelTest, TheTargetLinesBreakAtSpacesNotInAFigure) {
  frame();  // a font for CalcTextSize
  const std::string line = "Hausdorff 24.9 mm (10.2%), Chamfer 0.474 mm (0.193%)";
  const float whole = ImGui::CalcTextSize(line.c_str()).x;
  for (const float part : {0.35f, 0.5f, 0.62f, 0.8f}) {
    const float width = part * whole;
    const std::string wrapped = studio::wrapAtSpaces(line, width);
    std::string unwrapped = wrapped;
    std::replace(unwrapped.begin(), unwrapped.end(), '\n', ' ');
    EXPECT_EQ(unwrapped, line) << wrapped;
    EXPECT_NE(wrapped.find('\n'), std::string::npos) << wrapped;
    std::istringstream rows(wrapped);
    for (std::string row; std::getline(rows, row);)
      EXPECT_LE(ImGui::CalcTextSize(row.c_str()).x, width) << "at " << width << ": " << row;
  }
  // A word wider than the width stays whole, on a row of its own.
  EXPECT_EQ(studio::wrapAtSpaces("a /very/long/path.obj b", 20.0f), "a\n/very/long/path.obj\nb");
}

// The wrapped lines keep the items where they are, as long as they fit the box's rows: a replay,
// whose lines say less, points at the same buttons.
TEST_F(StudioPanelTest, TheTargetLinesMoveNoItem) {
  expectItemsStay(
      [&] {
        stats_.targetLine = "target: a.obj";
        stats_.suggestionLine = "";
      },
      [&] {
        stats_.targetLine = "(measuring) " + distanceText(0.0244, 0.0244, 0.2001);
        stats_.suggestionLine = "suggestion 1 of 3: Chamfer 0.345 mm -> 0.000752 mm";
      });
}

// Issue 38, 4: ImGui draws a field's text from its start, so the target field showed a long
// path's folders and hid its file's name. The field shows the path's end, whole within its width.
TEST_F(StudioPanelTest, ALongTargetPathShowsItsFileName) {
  frame();  // a font for CalcTextSize
  const std::string path = "/work/main/examples/targets/a rather long folder name/vase.obj";
  const float width = 0.5f * ImGui::CalcTextSize(path.c_str()).x;
  const std::string shown = pathEnd(path, width);
  EXPECT_LE(ImGui::CalcTextSize(shown.c_str()).x, width) << shown;
  EXPECT_EQ(shown.rfind("..."), 0u) << shown;
  EXPECT_TRUE(shown.ends_with("/vase.obj")) << shown;
  EXPECT_GT(shown.size(), std::string(".../vase.obj").size()) << "as much as fits: " << shown;
  EXPECT_EQ(pathEnd("vase.obj", width), "vase.obj");  // a path that fits is shown whole
  // A character of several bytes is never cut.
  const std::string utf8 = pathEnd("/h\xc3\xa9h\xc3\xa9h\xc3\xa9h\xc3\xa9/x.obj", 30.0f);
  EXPECT_TRUE(isUtf8(utf8)) << utf8;
}

}  // namespace
}  // namespace curvefold::studio
