#include "app/studio/studio_replay.hpp"

#include <functional>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/session/document.hpp"
#include "app/studio/headset_studio.hpp"

namespace curvefold::studio {

namespace {

// A design and the headset studio over it, as a recording's header sets them up. The studio
// writes no files: a replay or a script makes the design, not the session's files.
struct StudioFromHeader {
  StudioFromHeader(const RecordingHeader& header, const std::string& name, bool replaying)
      : doc(session::makeDocument(Design{header.surface, {}, header.symmetry}, name,
                                  header.sheetFrame, header.handedness)),
        studio(doc, optionsFor(header, name, replaying), hostWritingNothing()) {}

  static HeadsetStudioOptions optionsFor(const RecordingHeader& header, const std::string& name,
                                         bool replaying) {
    HeadsetStudioOptions options;
    options.recent = header.studio ? header.studio->recent : std::vector<std::string>{};
    options.sheetFrame = header.sheetFrame;
    options.name = name;
    options.replaying = replaying;
    return options;
  }
  static HeadsetStudioHost hostWritingNothing() {
    HeadsetStudioHost host;
    host.writeFile = [](const std::string&, const std::function<void(const std::string&)>&) {};
    return host;
  }

  session::Document doc;
  HeadsetStudio studio;
};

class StudioGestureWorld : public GestureWorld {
 public:
  explicit StudioGestureWorld(const RecordingHeader& header) : world_(header, "script", false) {}

  void process(const InputFrame& frame) override { world_.studio.process(frame); }
  const InteractionCore& core() const override { return *world_.doc.core; }
  std::optional<glm::dvec3> panelItem(const std::string& label) const override {
    return world_.studio.itemWorld(label);
  }
  std::optional<glm::dvec3> panelFacing() const override { return world_.studio.facing(); }

 private:
  StudioFromHeader world_;
};

}  // namespace

ReplayResult replayStudioRecording(const Recording& recording, const ReplayOptions& options) {
  if (!recording.header.studio)
    throw std::invalid_argument("replayStudioRecording: the recording has no studio");
  // Dear ImGui's current context is one pointer for the whole process (GImGui), so replays in
  // several threads (the Python module's) take turns rather than draw into each other's panel.
  static std::mutex oneReplayAtATime;
  const std::lock_guard<std::mutex> turn(oneReplayAtATime);
  StudioFromHeader replayed(recording.header, "recording", true);
  session::Document& doc = replayed.doc;

  ReplayResult result;
  result.duration = replayFrames(recording, options, [&](const InputFrame& frame) {
    const FoldSession* before = doc.session.get();
    const std::size_t foldsBefore = doc.session->foldCount();
    const std::size_t trianglesBefore = doc.session->fixed().triangleCount();
    replayed.studio.process(frame);
    // A new sheet starts its fold count again; its events are logged against it.
    appendFoldLog(
        result.log, *doc.session, doc.core->events(), frame.time,
        doc.session.get() == before ? foldsBefore : 0,
        doc.session.get() == before ? trianglesBefore : doc.session->initial().triangleCount());
  });
  result.design = doc.design();
  result.sheet = doc.session->fixed();
  result.frameCount = recording.frames.size();
  result.endedWhileDragging = doc.session->dragging();
  if (const LiveSimulation* simulation = doc.core->simulation())
    result.simulated = simulation->sheet().positions;
  return result;
}

ReplayResult replayAnyRecording(const Recording& recording, const ReplayOptions& options) {
  return recording.header.studio ? replayStudioRecording(recording, options)
                                 : replayRecording(recording, options);
}

GestureWorldFactory studioGestureWorld() {
  return [](const RecordingHeader& header) -> std::unique_ptr<GestureWorld> {
    return std::make_unique<StudioGestureWorld>(header);
  };
}

}  // namespace curvefold::studio
