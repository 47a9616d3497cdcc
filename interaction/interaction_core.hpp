// The two-handed interaction core (docs/design.md 5): consumes input frames and drives a
// FoldSession. The non-dominant hand holds the sheet frame while its clutch is squeezed; the
// dominant hand's point hovers, grabs a surface point with the trigger and drags it, and release
// commits. Moving either hand during a drag folds, since the target is taken in sheet coordinates.
// With both squeezes held (and no drag), the sheet moves, turns and scales uniformly between the
// hands, as in Open Brush and Gravity Sketch: the scale is a view scale, the design stays in
// metres.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "interaction/hand_side.hpp"
#include "interaction/input_frame.hpp"
#include "interaction/live_simulation.hpp"
#include "interaction/surface_picker.hpp"

namespace curvefold {

// Thresholds of the interaction, in one place.
struct InteractionThresholds {
  // The point hovers the nearest surface point within this distance (metres): about the size of a
  // controller's tip, so a point can be picked without touching the paper exactly.
  double hoverRadius = 0.03;
  // The view scale two hands can reach, and the hand span below which they hold it still.
  double minimumViewScale = 0.05;
  double maximumViewScale = 20.0;
  double minimumHandSpan = 0.02;
  // Trigger and grip hysteresis: pressed at or above `press`, released at or below `release`, so a
  // noisy value near one threshold does not start and stop drags or clutches.
  double selectPress = 0.75;
  double selectRelease = 0.25;
  double clutchPress = 0.75;
  double clutchRelease = 0.25;
  // A drag folds only once the target has moved this far (metres) from the grabbed point, so a
  // click without intent adds no fold; a release before that cancels.
  double minimumDragDistance = 0.002;
  // Bare hands (interaction/hand_input.hpp), distances in metres, not the 0..1 values above: a
  // pinch starts when the thumb and index tips come this close and ends when they part this far; a
  // hand is closed (the clutch) when its fingertips come within handClosedBelowMetres of the palm
  // on average (fingertipsToPalm), and open again from handOpenAboveMetres. The gaps between press
  // and release are wider than tracking jitter, so jitter neither starts nor drops a fold. A tap
  // (the thumb on another fingertip) uses the pinch distances.
  double pinchPress = 0.015;
  double pinchRelease = 0.035;
  double handClosedBelowMetres = 0.055;
  double handOpenAboveMetres = 0.08;
  // The One Euro filters (Casiez et al., CHI 2012) on a hand's pinch point and palm: cutoff at
  // rest (Hz), how fast it rises with speed (per m/s), and the cutoff of the speed estimate (Hz).
  // Tuned on the example recordings with 2 mm of jitter (docs/design.md 5b): the point is steady
  // at rest and within about a millimetre where a pinch starts or ends.
  double handFilterMinCutoff = 1.0;
  double handFilterBeta = 50.0;
  double handFilterDerivativeCutoff = 2.0;
  // The same for the palm's orientation, rising per rad/s: quick, since the sheet turns with it.
  double handRotationFilterMinCutoff = 1.0;
  double handRotationFilterBeta = 10.0;
  // ... and for the aim's direction (the panel ray, levered out to the panel): slow.
  double handAimFilterMinCutoff = 2.0;
  double handAimFilterBeta = 2.0;
};

// Not a threshold to tune but a guard (metres): a hand whose knuckles lie within this of the back
// of the hand (joints collapsed by the tracker) points nowhere. These are metres of the user's
// world, not of the sheet, so they stay here, not among the geometry's tolerances.
inline constexpr double kShortestPointingSpan = 1e-6;

enum class InteractionState { Idle, Hover, Dragging };

// What the point hand serves this frame: the sheet, or a panel its ray is on. On a panel the tip
// neither hovers nor grabs (a drag already under way goes on), so pointing at a button over the
// sheet does not fold it.
enum class PointTarget { Sheet, Panel };

enum class InteractionEventKind { Grab, Commit, Cancel, Undo, Redo, SwitchHands };

// Something that happened in the last frame; Grab and Commit also ask for a haptic pulse.
struct InteractionEvent {
  InteractionEventKind kind;
  double time = 0.0;
};

enum class HapticHand { Sheet, Point };
struct HapticPulse {
  HapticHand hand = HapticHand::Point;
  double amplitude = 0.5;  // 0..1
  double duration = 0.02;  // seconds
};

// What the hands feel: a faint tick entering hover, a firmer one on a grab, the strongest on a
// commit.
inline constexpr HapticPulse kHoverEnterPulse{HapticHand::Point, 0.15, 0.01};
// A drag starts to pass the sheet through itself: short and distinct from the grab's.
inline constexpr HapticPulse kIntersectionPulse{HapticHand::Point, 0.6, 0.01};

struct HoverPoint {
  SurfacePoint point;           // on the fixed sheet
  glm::dvec3 sheetPosition{0};  // sheet coordinates
  double distance = 0.0;        // from the tip, metres
};

class InteractionCore {
 public:
  InteractionCore(FoldSession& session, const Pose& worldFromSheet,
                  HandSide handedness = HandSide::Right,
                  const InteractionThresholds& thresholds = {});

  // Consumes one frame. Frames must come in time order.
  void process(const InputFrame& frame, PointTarget target = PointTarget::Sheet);

  // --- What a renderer shows ----------------------------------------------------------------
  InteractionState state() const { return state_; }
  // world = worldFromSheet().apply(viewScale() * sheet point).
  const Pose& worldFromSheet() const { return worldFromSheet_; }
  double viewScale() const { return viewScale_; }
  glm::dvec3 worldOf(const glm::dvec3& sheetPoint) const {
    return worldFromSheet_.apply(viewScale_ * sheetPoint);
  }
  glm::dvec3 sheetOf(const glm::dvec3& worldPoint) const {
    return worldFromSheet_.inverse().apply(worldPoint) / viewScale_;
  }
  bool clutched() const { return clutched_; }
  // Both hands hold the sheet (moving, turning and scaling it).
  bool twoHanded() const { return twoHanded_; }
  // Puts the sheet back where the session started it, at scale 1 (the panel's "reset view").
  void resetView();
  // The dominant hand, which holds the point (sources map controllers and hands to roles by it).
  HandSide handedness() const { return handedness_; }
  const std::optional<HoverPoint>& hover() const { return hover_; }
  // While dragging: the grabbed point's start and its current target, in sheet coordinates.
  glm::dvec3 grabStart() const { return session_.grabbedPoint(); }
  glm::dvec3 grabTarget() const { return session_.dragTarget(); }
  // The reflection plane (sheet coordinates) while a drag folds the sheet.
  std::optional<ReflectionPlane> plane() const;
  // Triangles of the displayed sheet that lie in the reflected part (empty unless folding).
  const std::vector<TriangleIndex>& reflectedTriangles() const;
  // While dragging: how many triangle pairs the reflected part crosses the rest in, and their
  // triangles (of the displayed sheet); both empty otherwise (engine/geometry/self_intersection).
  std::size_t intersectionPairs() const { return watch_.pairCount(); }
  const std::vector<TriangleIndex>& intersectingTriangles() const { return watch_.triangles(); }
  // The pairs the last committed fold crossed in, as the drag ended.
  std::size_t lastCommitIntersections() const { return lastCommitIntersections_; }
  // The studio's suggested fold on offer (frames bring them, InputFrame::suggestions), while the
  // design is the one they were made for and no drag is under way; null otherwise.
  // Button::TakeSuggestion makes it, Button::NextSuggestion offers the next one (round), and a
  // grab within the hover radius of its grabbed point takes that point with the fold already
  // made, for the hand to adjust from there (the designer has the last word).
  const SuggestedFold* offeredFold() const;
  // Which of how many is on offer (0-based); 0 of 0 when none.
  std::size_t offerIndex() const { return offeredFold() ? offerIndex_ : 0; }
  std::size_t offerCount() const { return offeredFold() ? offers_.size() : 0; }
  const FoldSession& session() const { return session_; }
  // The live simulation while frames carry one (InputFrame::simulation), else null: made from the
  // committed design when the first such frame comes (again when the design changes: an undo),
  // dropped when one comes without. While it runs the point hand neither hovers nor folds (a
  // drag under way is cancelled); the sheet hand holds the sheet as ever. The design is untouched.
  const LiveSimulation* simulation() const { return simulation_.get(); }
  // Simulations made from now on step on a worker thread (LiveSimulation's onWorker: the live
  // window draws while the next state is computed, one frame behind); replays leave it off.
  void setSimulationOnWorker(bool on) { simulationOnWorker_ = on; }
  // What makes the solver of frames asking for the GPU (SimulationInput::solver): the host's
  // Vulkan compute solver (app/desktop/gpu_live_solver.hpp). Without one such frames simulate
  // nothing and simulationProblem() says so (a replay never has one). Changing the solver a frame
  // asks for starts the simulation again from flat.
  void setGpuSolver(LiveSolverFactory factory) { gpuSolver_ = std::move(factory); }
  // Drops the simulation (the next frame with one starts again from flat): a host whose device
  // goes before the core lets its GPU solver go first.
  void endSimulation();
  // Why the last frame's simulation could not be made (a sheet the model refuses), else empty.
  const std::string& simulationProblem() const { return simulationProblem_; }

  // What happened in the last processed frame, and the haptic pulses it asks for.
  const std::vector<InteractionEvent>& events() const { return events_; }
  const std::vector<HapticPulse>& haptics() const { return haptics_; }

  const InteractionThresholds& thresholds() const { return thresholds_; }

 private:
  void handleButtons(const InputFrame& frame);
  void handleSheetHand(const InputFrame& frame);
  // Both hands on the sheet: true while they hold it (the one-hand clutch then waits).
  bool handleTwoHands(const InputFrame& frame);
  void handlePointHand(const InputFrame& frame, PointTarget target);
  void endDrag(bool commit, double time);
  // Makes, advances or drops the live simulation for this frame; true while it runs.
  bool handleSimulation(const InputFrame& frame);
  // Starts a drag of the offered fold, already at its drop point. False (and the offer dropped)
  // when its seed is not on the sheet (a recording's mistake).
  bool dragOffered(double time);
  void emit(InteractionEventKind kind, double time);
  const SurfacePicker& picker();

  FoldSession& session_;
  InteractionThresholds thresholds_;
  HandSide handedness_;
  InteractionState state_ = InteractionState::Idle;
  std::vector<InteractionEvent> events_;
  std::vector<HapticPulse> haptics_;

  // Sheet hand.
  Pose initialWorldFromSheet_;
  Pose worldFromSheet_;
  double viewScale_ = 1.0;
  bool clutched_ = false;
  bool clutchAnchored_ = false;  // false while the hand is lost during a clutch
  Pose handAtClutch_;
  Pose sheetAtClutch_;

  // Both hands: where they were when they took the sheet, and the sheet then.
  bool gripHeld_ = false;  // the point hand's squeeze
  bool twoHanded_ = false;
  glm::dvec3 sheetHandAtTwoHands_{0.0}, pointHandAtTwoHands_{0.0};
  Pose sheetAtTwoHands_;
  double scaleAtTwoHands_ = 1.0;

  // Point hand.
  bool selectHeld_ = false;
  std::uint32_t buttonsHeld_ = 0;
  std::optional<HoverPoint> hover_;
  bool quietHover_ = false;  // a drag just ended: the hover that follows does not tick
  glm::dvec3 grabOffset_{
      0.0};  // sheet coordinates: target = inverse(worldFromSheet) * tip + offset
  bool pointAnchored_ = false;  // false while the point hand is lost during a drag
  bool dragMoved_ = false;      // the target has left the minimum drag distance
  glm::dvec3 lastTarget_{0.0};

  std::unique_ptr<SurfacePicker> picker_;
  std::uint64_t pickerRevision_ = ~std::uint64_t{0};

  // The drag's self-intersections, on a tree of the sheet built at the grab.
  DragIntersectionWatch watch_;
  std::size_t lastCommitIntersections_ = 0;

  // Suggestions on offer, for the design at offerRevision_.
  std::vector<SuggestedFold> offers_;
  std::size_t offerIndex_ = 0;
  std::uint64_t offerRevision_ = 0;

  std::unique_ptr<LiveSimulation> simulation_;
  // The design's fixedRevision it was made from (or failed to be made from).
  std::optional<std::uint64_t> simulationRevision_;
  std::string simulationProblem_;
  bool simulationOnWorker_ = false;
  LiveSolverKind simulationSolver_ = LiveSolverKind::Cpu;
  LiveSolverFactory gpuSolver_;
};

}  // namespace curvefold
