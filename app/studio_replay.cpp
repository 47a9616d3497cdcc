#include "app/studio_replay.hpp"

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/document.hpp"
#include "app/headset_studio.hpp"

namespace curvefold::studio {

ReplayResult replayStudioRecording(const Recording& recording, const ReplayOptions& options) {
  if (!recording.header.studio)
    throw std::invalid_argument("replayStudioRecording: the recording has no studio");
  session::Document doc =
      session::makeDocument(Design{recording.header.surface, {}, recording.header.symmetry},
                            "recording", recording.header.sheetFrame, recording.header.handedness);
  HeadsetStudioOptions studioOptions;
  studioOptions.recent = recording.header.studio->recent;
  studioOptions.sheetFrame = recording.header.sheetFrame;
  studioOptions.name = "recording";
  studioOptions.replaying = true;
  HeadsetStudioHost host;
  // A replay makes the design, not the session's files.
  host.writeFile = [](const std::string&, const std::function<void(const std::string&)>&) {};
  HeadsetStudio studio(doc, studioOptions, host);

  ReplayResult result;
  result.duration = replayFrames(recording, options, [&](const InputFrame& frame) {
    const FoldSession* before = doc.session.get();
    const std::size_t foldsBefore = doc.session->foldCount();
    const std::size_t trianglesBefore = doc.session->fixed().triangleCount();
    studio.process(frame);
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
  return result;
}

ReplayResult replayAnyRecording(const Recording& recording, const ReplayOptions& options) {
  return recording.header.studio ? replayStudioRecording(recording, options)
                                 : replayRecording(recording, options);
}

namespace {

class StudioGestureWorld : public GestureWorld {
 public:
  explicit StudioGestureWorld(const RecordingHeader& header)
      : doc_(session::makeDocument(Design{header.surface, {}, header.symmetry}, "script",
                                   header.sheetFrame, header.handedness)),
        studio_(doc_, optionsFor(header), hostWritingNothing()) {}

  void process(const InputFrame& frame) override { studio_.process(frame); }
  const InteractionCore& core() const override { return *doc_.core; }
  std::optional<glm::dvec3> panelItem(const std::string& label) const override {
    return studio_.itemWorld(label);
  }
  std::optional<glm::dvec3> panelFacing() const override { return studio_.facing(); }

 private:
  static HeadsetStudioOptions optionsFor(const RecordingHeader& header) {
    HeadsetStudioOptions options;
    options.recent = header.studio ? header.studio->recent : std::vector<std::string>{};
    options.sheetFrame = header.sheetFrame;
    options.name = "script";
    return options;
  }
  static HeadsetStudioHost hostWritingNothing() {
    HeadsetStudioHost host;
    host.writeFile = [](const std::string&, const std::function<void(const std::string&)>&) {};
    return host;
  }

  session::Document doc_;
  HeadsetStudio studio_;
};

}  // namespace

GestureWorldFactory studioGestureWorld() {
  return [](const RecordingHeader& header) -> std::unique_ptr<GestureWorld> {
    return std::make_unique<StudioGestureWorld>(header);
  };
}

}  // namespace curvefold::studio
