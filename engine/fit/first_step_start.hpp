// The start chosen by where its first step lands (issue 38, 2), toward a smooth target with no
// axis of revolution (a saddle, a chip): a sheet that starts nearer is not always the one that
// folds nearer. From a flat sheet the first step is a cross (pleat_folds.hpp: both ends of one
// line bent, both ends of the line across pleated), which takes the example saddle from 3.62% to
// 0.835% Chamfer, where the swept parabola, nearer at the start (2.71%), ends its fit at 1.81%.
//
// Paper given back: the cross's pleats fold paper away (twice each pleat's width, widened where
// the bent sheet rises along the hinge) and its bends shorten their ends' reach across the sheet
// (a turned end's projection), so a flat sheet cut to the target's footprint ends short of it
// (the example saddle's pleated ends at x = +-0.080 of the target's +-0.1: its Hausdorff point).
// paperGivenBack measures, after the first cross, how far each of the four ends falls short of
// the target's reach along that end's direction (in the sheet's plane, from its centre) and grows
// the sheet by as much there: a rectangle along the cross's first line (a square of its larger
// side when the kind is fixed to a square), whose own first cross then lands at the target's ends.
//
// Inputs: candidate starts (placed or sized sheets; PlacedStart), the fitter of the target, a
// deadline (the start's share of --time; the candidates after the first are tried only while it
// allows). Output: each candidate's first step (suggestPleats, the best one) measured exactly
// (surface_distance.hpp, kChoiceSamples), scored by Chamfer + 0.5 Hausdorff (the goal
// bounds both), and the best; a grown sheet is measured with its corners that stand out
// tucked under (tuck_folds.hpp), as the fit's end tucks them. Known limits: the growth is measured
// once (not iterated); a grown sheet's corners may stand past a round target's rim; the first step
// of a curved sheet is its pleats alone here (the fit's search of single folds beside them is left
// out, for the time).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "engine/fit/deadline.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/placed_start.hpp"
#include "engine/fit/ring_folds.hpp"
#include "engine/fit/start_surface.hpp"

namespace curvefold {

// The flat sheet `flat` grown where its first step `step` (a cross from it) ended short of
// `target` (see above): with `kind` "rectangle" a rectangle along the cross's first line,
// "square" a square of its larger side, "disk" a disk about the same centre grown to the end that
// fell shortest, "ellipse" `flat` scaled about its centre (development alike) to that end. `share`
// of each shortfall is given back (startByFirstStep tries all and half: a grown sheet's corners
// stand past a rounded footprint). Each end's shortfall is also counted against the target's arc
// length along it (its samples in a strip about the end's line, the polyline of their binned mean
// heights): a steep saddle's rising end is longer along its surface than its reach across the
// sheet. None where no end fell short by over 0.5% of the sheet's size, or `flat` is not flat.
std::optional<PlacedStart> paperGivenBack(const Sheet& flat, const FoldSuggestion& step,
                                          const TriangleMesh& target, const std::string& kind,
                                          double share = 1.0);

struct FirstStepStart {
  PlacedStart start;
  double chamfer = 0.0, hausdorff = 0.0;  // after its first step, metres
  double startChamfer = 0.0;              // before it
  bool grown = false;                     // paperGivenBack's sheet won
  bool cutShort = false;                  // the deadline left candidates untried
  // reviseTubeByFirstStep: where the start it replaced landed after its first step (m).
  double replacedChamfer = 0.0, replacedHausdorff = 0.0;
};

// Of `candidates` (and, for each flat one whose first step is a fold, its sheet with all and with
// half the paper given back: a disk's a disk, an ellipse's an ellipse, else a rectangle, or with
// `square` a square), the
// one whose first step lands nearest. None when
// `candidates` is empty.
std::optional<FirstStepStart> startByFirstStep(const std::vector<PlacedStart>& candidates,
                                               const FoldFitter& fitter, const Deadline& deadline,
                                               bool square = false);

// chooseStart's `start` toward a smooth target with no axis (fitter.smoothTarget(), not
// revolutionTarget()), `kind` "", "square", "rectangle" or "disk": the start itself and, where it
// is not flat and no kind was named, the squares, the rectangle, the disks and (an oblong round
// footprint's) the ellipses cut to the target's footprint (footprintStarts; the disks alone for
// "disk"), each with its paper given back, and (kind "", "square" or "rectangle") the sheet bent
// along the target's curvatures (bent_start.hpp; a square under "square", else a rectangle; not
// one with over twice the target's area), measured with its rulings' ends tucked under as the
// fit tucks them, compared
// by their first steps; a flat square or rectangle that wins is then folded toward the target's
// wings (wing_start.hpp) and replaced by that sheet where its first step (its tucks measured too)
// lands nearer; `start` becomes the winner (placed) when that is not `start` itself. None
// (and `start` untouched) where the rule does not apply (a creased start: the target was folded
// from it) or `start` won.
std::optional<FirstStepStart> reviseByFirstStep(StartChoice& start, const FoldFitter& fitter,
                                                const std::string& kind, const Deadline& deadline);

// chooseStart's `start` toward a smooth target of revolution (fitter.revolutionTarget(): a vase),
// `kind` "" or "cone": the start (a tube about the target's axis, tubeAbout) and the cone around
// the target's profile (enclosingCone: through the belly and the lip), compared by where their
// first step lands: the tube rings' chains (ring_folds.hpp) of up to `rings` rings each (two: the
// foot and the neck), measured exactly (4000 samples), by the Chamfer distance, with a guard: the
// cone around is taken only where its rings land nearer by Chamfer and no farther by Hausdorff
// (without it the lathe vase's fit ended farther by Hausdorff than its start: 7.06% -> 10.2%).
// The Chamfer distance is not traded against the Hausdorff one: two rings
// are a chain cut short, whose Hausdorff point is the end a later ring narrows (the example vase:
// the cone around 2.88 mm / 20.2 mm after two rings, 2.5 mm / 7.4 mm after its whole chain; the
// cone inside 3.25 / 7.4 mm, 2.9 / 5.9 mm). Rings only narrow a
// tube, so a cone fitted through the profile, nearer at the start, leaves the belly that stands
// outside it where it is (the example vase: up to 5.8 mm), while the cone around it is narrowed
// toward the neck and the foot; a gourd's waist between two bellies the cone around does not
// reach, and the nearer cone wins there. `start` becomes the winner (placed) when that is not
// `start` itself. None (and `start` untouched) where the rule does not apply (a creased start,
// a target with no axis, a start that is no tube about the axis, the widest tube chosen by the
// rings' reach: StartChoice::widestTube) or `start` won. The enclosing
// cone is tried only while `deadline` allows once the start's own step is measured.
// `handed`: the winner's chains as the probe grew them (ring_folds.hpp, TubeChains; set whichever
// start won, whenever the probe ran), for the search to grow on (FitOptions::tubeChains) rather
// than grow the same rings again.
std::optional<FirstStepStart> reviseTubeByFirstStep(StartChoice& start, const FoldFitter& fitter,
                                                    const std::string& kind,
                                                    const Deadline& deadline, std::size_t rings = 2,
                                                    TubeChains* handed = nullptr);

}  // namespace curvefold
