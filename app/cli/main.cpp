// curvefold: design curved-fold origami by reflection (Mitani & Igarashi 2011).
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <iostream>
#include <new>
#include <string>

#include <CLI/CLI.hpp>

#include "app/cli/commands.hpp"
#include "engine/text/environment_choice.hpp"
#include "engine/text/excerpt.hpp"

namespace {

// The last guard on "one line": a message quoting a value this program did not cut (CLI11 quotes
// an option's value whole) keeps its head and tail, with control characters escaped.
std::string oneLine(const std::string& message) {
  constexpr std::size_t kPart = 110;
  std::string text = message.size() > 2 * kPart + 5 ? message.substr(0, kPart) + " ... " +
                                                          message.substr(message.size() - kPart)
                                                    : message;
  std::string line;
  for (char c : text) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) {
      const std::string escaped = curvefold::quotedExcerpt(std::string(1, c));
      line += escaped.substr(1, escaped.size() - 2);  // without its quotes
    } else {
      line += c;
    }
  }
  return line;
}

// Memory held back for the way out of an allocation that fails. nlohmann's json allocates while it
// is destroyed (a stack as long as the array), so an exception unwinding through a large document
// with no memory left ended in std::terminate (`export --fold` under `ulimit -v`). A failure hands
// back one part of the reserve: while an exception unwinds (a destructor allocating) the
// allocation is tried again, else std::bad_alloc is thrown and main() says what ran out in one
// line. In parts, because a failure some code survives (the sheet cache treats one as a miss)
// must not spend the whole reserve that a later one needs.
constexpr std::size_t kUnwindReserveParts = 8;
constexpr std::size_t kUnwindReservePartBytes = 4u << 20;
std::array<std::atomic<char*>, kUnwindReserveParts> unwindReserve{};

void releaseUnwindReserve() {
  for (std::atomic<char*>& part : unwindReserve)
    if (char* held = part.exchange(nullptr)) {
      delete[] held;
      if (std::uncaught_exceptions() > 0) return;  // unwinding: operator new tries again
      throw std::bad_alloc();
    }
  std::set_new_handler(nullptr);
  throw std::bad_alloc();
}

}  // namespace

int main(int argc, char** argv) {
  for (std::atomic<char*>& part : unwindReserve)
    part = new (std::nothrow) char[kUnwindReservePartBytes];
  std::set_new_handler(releaseUnwindReserve);
  CLI::App app{"curvefold: design curved-fold origami by mirror reflection", "curvefold"};
  // No subcommand: XR with a headset, else the designer window, else a one-line pointer to
  // replay/render.
  app.require_subcommand(0, 1);
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return "curvefold: error: " + oneLine(e.what()) + " (see --help)\n";
  });
  curvefold::cli::addSurfacesCommand(app);
  curvefold::cli::addNewCommand(app);
  curvefold::cli::addFoldCommand(app);
  curvefold::cli::addExportCommand(app);
  curvefold::cli::addCheckCommand(app);
  curvefold::cli::addFitCommand(app);
  curvefold::cli::addDistanceCommand(app);
  curvefold::cli::addReplayCommand(app);
  curvefold::cli::addRecordScriptCommand(app);
  curvefold::cli::addRenderCommand(app);
  curvefold::cli::addSimulateCommand(app);
  curvefold::cli::addDesignCommand(app);
  curvefold::cli::addXrCommand(app);
  curvefold::cli::requireDecimalNumbers(app);
  try {
    // A misspelt setting (CURVEFOLD_REDRAW, CURVEFOLD_VK_VALIDATION) stops every command at once.
    curvefold::checkEnvironmentChoices();
    app.parse(argc, argv);
    if (app.get_subcommands().empty()) curvefold::cli::runDefault();
  } catch (const CLI::ParseError& e) {
    // CLI11 prints the line (failure_message) or the help; its own codes (106, 109, ...) are not
    // this program's: every refused command line exits 1, as every other bad input does.
    return app.exit(e) == 0 ? 0 : 1;
  } catch (const curvefold::cli::ExitStatus& e) {
    return e.status;
  } catch (const std::bad_alloc&) {
    // A reader that knows its input names it; this is the last resort, naming the command.
    std::string command;
    for (int i = 1; i < argc && command.size() < 120; ++i) command += std::string(" ") + argv[i];
    if (command.size() > 120) command = command.substr(0, 117) + "...";
    std::cerr << "curvefold: error: out of memory while running `curvefold" << command
              << "`: free memory, or use a coarser design (a lower --resolution)\n";
    return 1;
  } catch (const std::exception& e) {
    // Every failure is one line naming the problem; nothing half-written is left behind because
    // every file is written to a temporary and renamed.
    std::cerr << "curvefold: error: " << oneLine(e.what()) << "\n";
    return 1;
  }
  return 0;
}
