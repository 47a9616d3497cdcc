// The sheet to fold toward a shape no reflection sequence reaches (issue 38, 2): which catalogue
// surface, at which size, and with which of its symmetries, as a paper artist would start a vase
// from a tube and a bowl from a disk with pleats in a ring.
//
// The rule (docs/cli.md, `fit` without `--from` parameters): each candidate kind (the one named,
// or square, rectangle, disk, cylinder, half_cylinder and cone) is sized from the target in the
// catalogue's own frame (flat sheets lie in z = 0, the others turn about the y axis through the
// origin): a flat sheet gets the target's area (the paper it needs to cover it; a rectangle the
// proportions of the target's x and y extents), a cylinder the mean distance of the target from
// the y axis and its extent along y, a cone its mean radius over the lowest and the highest tenth
// of that extent. Each is made at its default resolution, and also at its defaults, and the one
// with the least Chamfer distance to the target (surface_distance.hpp, 4000 samples) is the
// start. A target with
// creases (a plane of its sharp edges, above the kind's own bends, holds 3% of its diagonal) was
// folded from a sheet as the catalogue makes it: that kind keeps its defaults, which the
// unfolding reads back onto. So was a target that is not curved (isCurved) with a kind's area at
// its defaults (within 1e-5: folds keep the area), though its creases are short (a corner turned)
// or none (folds whose planes missed the sheet moved it whole) and it reads as smooth: that kind
// at its defaults starts, before any nearer sheet, and no sheet is placed on it.
//
// The symmetry: of the rotations the start has (symmetryChoices), the highest order whose turn
// maps the target onto itself, within 1% of its diagonal on average and 3% at most (measured at
// 2000 area-uniform points); none when no rotation does.
//
// Placed sheets: the same kinds moved onto the target's principal axes (and the tube and cone
// about the axis it turns about, revolutionAxis, where no principal axis is it), and a swept
// parabola (placed_start.hpp), are candidates too when the target has no creases; the nearest of
// all wins. An oval bowl's (its footprint 1.12 times longer one way) include the disk of its area
// stretched to the footprint, kept only where it lies flat across the target's axis (the nested
// rings fold it); it is the rings' sheet below in place of the round disk.
// But without a kind asked for, the disk placed across a bowl's axis (revolutionAxis) wins over
// a nearer sheet when the nested rings' profile fit from it (nested_rings.hpp, 1 to 3 creases,
// seeded) scores within 0.75 of that sheet's distance, each as the goal weighs them (the model's
// mean plus a quarter of its farthest profile point, the sheet's Chamfer plus a quarter of its
// Hausdorff): the model is exact only along each flap's centre line, so the rings end 2-8 times
// farther than it says, but a placed cone, near at once, folds little closer and leaves a cup's
// bottom or a bowl's rim standing off (a footed bowl: cone 1.28% -> 1.01% of the diagonal, disk
// 3.57% -> 0.317%; a steep cup: cone Hausdorff 11%, the disk's rings 7.2%; docs/performance.md).
// The flat round sheets and this comparison are made also past the deadline (a loaded machine
// otherwise kept the cone for want of them; they cost a fraction of a second).
//
// Known limits: mirrors are not detected, only rotations, and only about the catalogue's axes (a
// placed start has none of them).
#pragma once

#include <optional>
#include <string>

#include "engine/fit/deadline.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/geometry/sheet.hpp"
#include "engine/geometry/triangle_mesh.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {

// A start the rule ranked just below its choice (StartChoice::runnersUp): a sheet placed on the
// target, and why it was close.
struct RunnerUpStart {
  std::string surface;
  SurfaceParameters parameters;
  std::optional<Sheet> placed;  // moved onto the target, as StartChoice::placed (else the kind
                                // in the catalogue's frame)
  std::string placement;        // how, for the user
  std::string why;              // the model's numbers that made it close, for the user
};

struct StartChoice {
  std::string surface;
  SurfaceParameters parameters;  // those the rule set (the rest at their defaults)
  double chamfer = 0.0;          // the start's distance to the target, metres
  // A sheet moved onto the target (placed_start.hpp), embedded in the design as it is: set when
  // it starts closer than every sheet in the catalogue's frame.
  std::optional<Sheet> placed;
  std::string placement;  // how, for the user
  // The target has creases this kind's sheet would not have (a fold's): the kind keeps its
  // defaults. Unset where the defaults were simply nearest.
  bool creased = false;
  // A symmetry was asked for and every sheet sized or placed to the target lacked it: the kind
  // at its defaults (which has it) instead.
  bool symmetryDefaults = false;
  // The deadline passed before every candidate was measured: the nearest of those measured.
  bool cutShort = false;
  // Without a kind asked for, the tube of a vase's widest radius replaced a tube about its axis
  // by the rings' reach (tube_reach.hpp): its rings are grown by the search, as from `--from
  // cylinder`, not weighed against the cone around by two rings (first_step_start.hpp).
  bool widestTube = false;
  // Without a kind asked for (or `cylinder`, whose tube's radius has an alternative), the starts
  // the rule's model ranked close below its choice, nearest first: the model does not foretell
  // where a fit ends (a steep cup's disk, chosen by its rings' profile within 0.70 of the placed
  // cone's, ended at 19.0% / 4.28% Hausdorff / Chamfer where the cone's fit ended at 8.90% /
  // 1.41%), so `fit` folds these too and keeps the design nearer by both measures. Close: the
  // choice's model within kRunnerUpMargin of the rule's own threshold (a disk's rings within 0.5
  // of the nearest sheet, where the rule takes the disk under 0.75; a vase's widest tube within
  // 0.9 of the cone's rings, where it takes the tube under 0.6); a bowl's disk (its rings within
  // 0.13-0.39 of the cone) has none. `--from cylinder`: the tube at 0.9 of the widest radius
  // (docs/performance.md, vase23: nearer by both on 4 of 8 vases). Empty when a symmetry is asked
  // for, or the target was folded from a catalogue sheet.
  std::vector<RunnerUpStart> runnersUp;
};

// `kind`: a catalogue surface name, or "" for any of the candidates above. `symmetry` (as
// parseSymmetry reads it, "" none): only sheets that have it are candidates, so a design asking
// for a mirror or a rotation keeps it (a sheet placed on the target's axes seldom has one; the
// kind at its defaults is the last resort). Throws SurfaceError when the named kind cannot be
// sized to the target, InvalidSymmetry when `symmetry` is no symmetry or no candidate has it.
// Past `deadline` (a share of a fit's time) no further candidate is measured once one is: each
// costs two distance measures, seconds on a target of 30,000 triangles (docs/performance.md).
StartChoice chooseStart(const TriangleMesh& target, const std::string& kind = "",
                        const std::string& symmetry = "", const Deadline& deadline = {});
// The same with the target's tree and samples made once (FoldFitter::measuredTarget()): on a
// large target most of what each candidate's measure cost.
StartChoice chooseStart(const MeasuredSurface& target, const std::string& kind = "",
                        const std::string& symmetry = "", const Deadline& deadline = {});

// Whether the target is a shape no reflection design reaches exactly: smooth (no plane of edges
// bent more than a gridded smooth shape bends) or a noisy scan (sharp edges everywhere, not along
// the few curves a fold makes: over a fifth of its edge length sharp, or the plane holding most
// sharp edges holds under 2% of them, or under half of the edges in that plane are sharp, as in a
// row of a depth scan's grid), or curved (not developable: a quarter of its interior vertices
// have an angle defect, as on a coarse grid of a hemisphere whose rings bend like creases). A
// target folded from a catalogue sheet is none of these. Such a target
// gets sheets placed on it (above) and the search's rings and pleats (fold_fit.hpp). Cost: the
// sharp share and the curvature (a few passes over the edges) decide a scan or a curved shape
// alone; the plane search (hundreds of passes over the sharp edges) runs only when they do not.
bool isSmoothOrScanned(const TriangleMesh& target);

// Whether the target is curved like no reflection design is: a quarter of its interior vertices
// have an angle defect (a folded sheet, creases and all, is isometric to its flat development,
// so it has none; a vase, a bowl, a saddle or a scan's noise has one nearly everywhere). A fine
// grid of a gentle shape may fall under the defect's floor (1e-3 rad) and read as not curved.
bool isCurved(const TriangleMesh& target);

// The target's rotational symmetry among the sheet's ("rotational:12:y"), or "" for none.
std::string detectRotationalSymmetry(const TriangleMesh& target, const Sheet& initial);
std::string detectRotationalSymmetry(const MeasuredSurface& target, const Sheet& initial);

}  // namespace curvefold
