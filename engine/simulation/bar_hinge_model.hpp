// The bar-and-hinge model of a folding sheet (docs/design.md, "Simulating the fold"), after
// Ghassaei, Demaine & Gershenfeld, "Fast, Interactive Origami Simulation using GPU Computation"
// (7OSME, 2018): every edge of the triangulated crease pattern is an axial bar that keeps its
// length; every interior edge is a hinge between its two triangles, driven toward a target fold
// angle. Crease hinges aim at their crease's angle times the fold amount (0 to 1); facet hinges
// aim at their facet's angle (0: flat, or in design mode the design's own bending) and either
// keep the faces stiff (design mode) or bend with paper's stiffness (paper mode).
//
// Energy: bars 1/2 k (l - L)^2, hinges 1/2 k (theta - target)^2, glued vertex pairs 1/2 k |xi -
// xj|^2; pinned vertices do not move. A crease also resists leaving its side of flat: along its
// side (q = theta for a valley, -theta for a mountain) it adds 1/2 kw q^2 below 0 and
// 1/2 kw (q - pi)^2 past pi, kw ten facets' stiffness by default (ModelOptions::wrongSideScale),
// so a mountain stays a mountain as paper's does, and the sheet bends instead where the pattern
// cannot fold with rigid faces. The dihedral angle theta is the FOLD convention of
// creases.hpp (positive valley), tracked through +-180 degrees by unwrapping against the last
// known angle (hingeAngle's `previous`).
//
// Layout: flat index arrays only, and each element's force goes into its own slots of one force
// buffer, which every vertex then sums over a fixed list (gatherOffsets/gatherSlots): no atomics,
// no pointers, the same result for any thread count, and a compute-shader port is one kernel per
// element kind plus one per vertex.
//
// Stiffnesses: design mode uses nominal ones (bars axialStiffness / L, hinges stiffness x edge
// length; Origami Simulator's form); paper mode uses paper's: bars E t A_e / L^2 (A_e: a third of
// the edge's triangles' area), bending edges 6 D (discrete shells' 3 D |e|^2 / (A1 + A2), Grinspun
// et al. 2003, for triangles of height |e| / 2 on each side) with D = E t^3 / (12 (1 - nu^2)),
// creases D |e| / creaseLength. A hinge with a triangle lower than |e| / 2 (a sliver, which
// reflection cuts make) is weakened by that ratio: its angle turns by 1 / height for a unit move of
// the wing, and unweakened its forces would swamp every other and stall the solvers.
//
// Self-contact (contact.hpp): in paper mode, layers keep at least the paper's thickness apart by
// a barrier between each vertex and the triangles near it that are not its own (modelEnergy
// includes it; the solvers add its force). Design mode has none.
//
// Known limits: a hinge whose triangle degenerates has no
// angle (its force is 0 while it stays degenerate).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <glm/vec3.hpp>

#include "engine/io/crease_pattern.hpp"
#include "engine/simulation/contact.hpp"

namespace curvefold {

// A crease pattern the model cannot be built from (an edge with three triangles, triangles of
// opposite orientation across an edge, an edge no triangle has, a value that is not finite).
class SimulationInputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class SimulationMode : std::uint8_t {
  Design,  // every edge driven to its angle x fold amount, stiff faces
  Paper,   // only creases driven; facets bend with paper's stiffness toward flat
};

// Paper's stiffness (paper mode). Defaults: 0.1 mm copy paper, E = 4 GPa, nu = 0.3; a crease as
// stiff per length as 5 mm of the sheet around it in bending.
struct PaperProperties {
  double thickness = 1e-4;     // m
  double youngsModulus = 4e9;  // Pa
  double poissonRatio = 0.3;   //
  double creaseLength = 5e-3;  // m: crease torsional stiffness per length = D / creaseLength
};

struct ModelOptions {
  SimulationMode mode = SimulationMode::Design;
  PaperProperties paper;
  // Design mode's nominal stiffnesses (per unit length for hinges): stiff bars and faces, soft
  // creases, so creases whose targets disagree (a Miura-ori between flat and folded) fold the
  // faces rigidly rather than stretch or bend them (at 100 / L bars the Miura-ori strained 1%).
  double axialStiffness = 2000.0;
  double facetStiffness = 200.0;
  double creaseStiffness = 1.0;
  // A crease's one-sided term (hinge_kernel.hpp's wrongSideExcess): stiffness against passing
  // through flat to the other side of its target, or past flat-folded, as this many times the
  // stiffness a facet hinge of the same edge would have (design: facetStiffness x length; paper:
  // the bending edges'), so the sheet bends its facets rather than fold a mountain as a valley
  // (the square twist, which cannot fold with rigid faces). 0: off (the symmetric energy alone).
  double wrongSideScale = 10.0;
  std::vector<std::uint32_t> pins;                            // vertices held where they start
  std::vector<std::pair<std::uint32_t, std::uint32_t>> glue;  // vertex pairs pulled together
  ContactOptions contact;  // paper mode's self-contact (contact.hpp)
};

// Origami Simulator's published stiffnesses (Ghassaei et al. 2018; js/globals.js and crease.js:
// axialStiffness 20 / L, creaseStiffness 0.7 L, panelStiffness 0.7 L for facet hinges, with the
// damping ratio 0.45 of DynamicOptions; its faceStiffness 0.2 holds each triangle's angles, a
// constraint this model does not have, and was taken here for the facets before): soft bars and
// facets as stiff as creases, so curved creases bend the paper between them and a pattern folds
// at once from flat; in design mode. The project's own defaults above keep faces rigid instead.
ModelOptions simulatorModelOptions();

// Paper mode as `curvefold simulate --paper` and Python's simulate(paper=...) both set it (one
// copy, so the two fold the same sheet to the same state bit for bit).
//
// Inputs:
//   options      the options to turn to paper mode (its other fields kept: pins, glue, ...)
//   thicknessMm  the paper's thickness, above 0 and at most 10 mm
//   modulusGpa   its Young's modulus, above 0 and at most 1000 GPa
//   contact      self-contact: layers kept the thickness apart, and edge pairs too, glued
//                seams or not (contact20: 47 of 126 paper runs crossed without them, 3 with)
// Outputs:
//   options      mode Paper, paper thickness and modulus in SI units, contact as above
// Throws std::invalid_argument for a value out of range, its message starting with the value's
// name and a colon ("paper: ..." or "modulus: ..."), for each caller to prefix as it names them.
void setPaperMode(ModelOptions& options, double thicknessMm, double modulusGpa, bool contact);

// setPaperMode's modulus when none is given (PaperProperties::youngsModulus's, in GPa).
inline constexpr double kDefaultPaperModulusGpa = 4.0;

// The hinge of an interior edge: a -> b is the edge as its left triangle (a, b, c) runs it; the
// right triangle is (b, a, d).
struct Hinge {
  std::uint32_t a = 0, b = 0, c = 0, d = 0;
};

struct BarHingeModel {
  SimulationMode mode = SimulationMode::Design;
  std::vector<glm::dvec3> flatPositions;  // the crease pattern at z = 0
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<double> mass;          // lumped, a third of the incident triangles' area, mean 1
  std::vector<std::uint8_t> pinned;  // per vertex

  // One bar per crease-pattern edge, in the pattern's edge order.
  std::vector<std::array<std::uint32_t, 2>> bars;
  std::vector<double> barLength;     // rest length
  std::vector<double> barStiffness;  // N/m (or nominal)
  std::vector<double> barDamping;    // 2 sqrt(k min(m_a, m_b)): times the damping ratio, per m/s

  // One hinge per interior edge.
  std::vector<Hinge> hinges;
  std::vector<std::uint32_t> hingeEdge;                      // which bar / pattern edge
  std::vector<std::array<std::uint32_t, 2>> hingeTriangles;  // left (a, b, c), right (b, a, d)
  std::vector<double> hingeTarget;                           // radians at fold amount 1
  // Paper mode: a facet hinge's angle as drawn (a design's own bending, which paper mode does not
  // drive), for the static solver's glued start; 0 for creases and in design mode.
  std::vector<double> hingeShape;
  std::vector<std::uint8_t> hingeCrease;  // 1: a crease (Mountain or Valley)
  std::vector<std::uint8_t> hingeDriven;  // 1: target scaled by the fold amount
  std::vector<double> hingeStiffness;     // per radian^2
  // Per hinge, the one-sided term's stiffness (per radian^2) signed by the crease's side (+
  // valley, - mountain; the sign of hingeTarget); 0 for facets, bridges and the hinges bridged.
  std::vector<double> hingeWrongSide;
  // Per hinge: 0 for an edge's own hinge; a bridge across slivers (bar_hinge_model.cpp) 1 when
  // it crosses facets only, 2 when it crosses a crease (its target then holds the crease's angle,
  // and may pass flat-folded: the sum of the targets it crosses). Empty for a model built by hand:
  // read it with bridgeKind.
  std::vector<std::uint8_t> hingeBridge;

  std::vector<std::array<std::uint32_t, 2>> glue;
  double glueStiffness = 0.0;

  ContactParameters contact;  // self-contact (contact.hpp); enabled in paper mode only

  // Force slots: bar i's ends at 2i, 2i+1; hinge j's a, b, c, d at hingeSlot0 + 4j..; glue g's at
  // glueSlot0 + 2g... Vertex v sums gatherSlots[gatherOffsets[v] .. gatherOffsets[v+1]) in order.
  std::size_t hingeSlot0 = 0, glueSlot0 = 0, slotCount = 0;
  std::vector<std::uint32_t> gatherOffsets;
  std::vector<std::uint32_t> gatherSlots;
  // The dynamic step's scatter (dynamic_solver.cpp): slot s's place in gather order (the inverse
  // of gatherSlots), where the step writes its force so that each vertex then reads its forces
  // in one run; the same sums bit for bit as gathering through gatherSlots.
  std::vector<std::uint32_t> scatterSlots;
  // Where each vertex's bar slots end in its run (they come first, bars' slots being the lowest):
  // the dynamic step keeps one force per bar in bar order (SimulationState::barForces) and its
  // ends read it there, +f at slot 2i, -f at 2i + 1, rather than through two scattered slots.
  std::vector<std::uint32_t> gatherBarEnd;

  // stableTimeStep(model) as built (dynamic_solver.hpp); recompute it after changing a stiffness.
  double timeStep = 0.0;

  // A folding motion (folding_motion.hpp), when one is set: every hinge's target at increasing
  // fold amounts from 0 to 1, motionTargets row by row (hinges.size() a row). Between two rows
  // the targets are interpolated linearly. Empty: the targets scale linearly with the amount.
  std::vector<double> motionAmounts;
  std::vector<double> motionTargets;

  std::size_t vertexCount() const { return flatPositions.size(); }
  // The hinge's target at a fold amount (0..1): along the motion when one is set, else driven
  // hinges scale and the others keep theirs.
  double target(std::size_t hinge, double foldAmount) const {
    if (!motionAmounts.empty()) return motionTarget(hinge, foldAmount);
    return hingeDriven[hinge] ? hingeTarget[hinge] * foldAmount : hingeTarget[hinge];
  }
  double motionTarget(std::size_t hinge, double foldAmount) const;
  // hingeBridge's value (0 where it is not set).
  std::uint8_t bridgeKind(std::size_t hinge) const {
    return hinge < hingeBridge.size() ? hingeBridge[hinge] : 0;
  }
};

// Builds the model. In design mode every interior edge is driven to its foldAngleDegrees times
// the fold amount (creases with crease stiffness; Flat and Unassigned edges, facets, with facet
// stiffness), so 0 is the flat pattern and 1 every edge's angle; in paper mode Mountain and
// Valley edges are creases driven so, and every other interior edge bends freely toward flat.
// Throws SimulationInputError for a pattern it cannot use.
BarHingeModel buildModel(const CreasePattern& pattern, const ModelOptions& options = {});

// The signed dihedral angle of a hinge (radians, positive valley), unwrapped to lie within pi of
// `previous`; 0 while either triangle is degenerate.
double hingeAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                  const glm::dvec3& d, double previous = 0.0);

// Both at once (the forces' kernel).
double hingeAngleWithGradient(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                              const glm::dvec3& d, double previous,
                              std::array<glm::dvec3, 4>& gradient);

// The angle's gradient with respect to a, b, c, d (zero while a triangle is degenerate).
std::array<glm::dvec3, 4> hingeAngleGradient(const glm::dvec3& a, const glm::dvec3& b,
                                             const glm::dvec3& c, const glm::dvec3& d);

// Every hinge's angle at these positions, unwrapped against `previous` (empty: against 0).
std::vector<double> hingeAngles(const BarHingeModel& model,
                                const std::vector<glm::dvec3>& positions,
                                const std::vector<double>& previous = {});

// Every hinge's target at a fold amount (0..1).
std::vector<double> hingeTargets(const BarHingeModel& model, double foldAmount);

// The model's energy at these positions toward these hinge targets, hinge angles unwrapped
// against `previous`, the contact barrier's included. Summed in a fixed order.
double modelEnergy(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                   const std::vector<double>& targets, const std::vector<double>& previous);

// modelEnergy(moved) - modelEnergy(positions), each element's change computed from the vertices'
// moves (moved - positions) rather than as a difference of two sums: accurate to the change's own
// size, where the difference of the sums is lost in their rounding (about 1e-16 of the energy)
// once a step's decrease falls below it, as it does near an equilibrium whose hinges keep large
// errors (a Huffman tower at 50%, where the static solver stalls at a residual of 5e-7); the
// static solver records each step's change with it (StaticIteration::energyChange). `angles`:
// every hinge's angle at `positions`, unwrapped; the moved angles are taken within pi of them.
// The contact barrier's change (paper mode) is the difference of its sums.
double modelEnergyChange(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                         const std::vector<glm::dvec3>& moved, const std::vector<double>& targets,
                         const std::vector<double>& angles);

// Every element's force on each of its vertices into its slots (slotForces, model.slotCount
// long) and every hinge's angle unwrapped against previous into angles (both may be the same
// vector). With velocities, bars resist their ends' relative speed along them (damping ratio
// dampingRatio: 2 zeta sqrt(k m)). Runs on all cores in one pass over every element (one barrier);
// each element writes only its own slots.
void elementForces(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                   const std::vector<double>& targets, const std::vector<double>& previous,
                   std::vector<double>& angles, std::vector<glm::dvec3>& slotForces,
                   const glm::dvec3* velocities = nullptr, double dampingRatio = 0.0);

// Each vertex's total force: the sum of its slots in gather order (0 for a pinned vertex).
void gatherForces(const BarHingeModel& model, const std::vector<glm::dvec3>& slotForces,
                  std::vector<glm::dvec3>& vertexForces);

// Calls body(begin, end) over [0, count) in ranges of about `grain` on all cores; for kernels
// that write only their own indices (the result is the same however TBB splits the range).
template <typename Body>
void forEachRange(std::size_t count, std::size_t grain, const Body& body) {
  if (count <= grain) {
    body(std::size_t(0), count);
    return;
  }
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, count, grain),
      [&](const tbb::blocked_range<std::size_t>& range) { body(range.begin(), range.end()); });
}

// Calls body(i) for i in [0, count) on all cores; for kernels that write only their own index,
// whose result is then the same however TBB splits the range.
template <typename Body>
void forEachIndex(std::size_t count, const Body& body) {
  constexpr std::size_t kGrain = 1024;
  if (count <= kGrain) {
    for (std::size_t i = 0; i < count; ++i) body(i);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, kGrain),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) body(i);
                    });
}

// A sheet's state while it folds: what the dynamic and static solvers advance.
struct SimulationState {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> velocities;
  std::vector<double> hingeAngles;        // unwrapped, as of the last step or iteration
  std::size_t steps = 0;                  // dynamic steps taken
  std::vector<glm::dvec3> slotForces;     // scratch: one force per element slot
  std::vector<glm::dvec3> barForces;      // scratch: the dynamic step's force of each bar on its a
  std::vector<double> targets;            // scratch: the hinge targets of the last step
  ContactList contactPairs;               // the dynamic solver's contact pairs (contact.hpp)
  std::vector<glm::dvec3> contactForces;  // scratch: each vertex's contact force, last step
};

// The flat crease pattern at rest.
SimulationState flatState(const BarHingeModel& model);

// Per pattern edge: (length - rest length) / rest length.
std::vector<double> edgeStrain(const BarHingeModel& model,
                               const std::vector<glm::dvec3>& positions);

// Per pattern edge: the crease's angle minus its target at the fold amount, degrees; 0 for an
// edge that is not a crease hinge.
std::vector<double> creaseAngleError(const BarHingeModel& model,
                                     const std::vector<glm::dvec3>& positions, double foldAmount,
                                     const std::vector<double>& previous = {});

}  // namespace curvefold
