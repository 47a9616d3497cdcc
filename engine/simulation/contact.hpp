// Self-contact of the bar-and-hinge model (issue 39, paper mode): layers of paper keep at least
// the paper's thickness apart. Each vertex and each triangle that is not its own are a pair; with
// d the point-triangle distance, s = d - thickness the gap left, and s^ the activation gap (the
// thickness again), a pair whose gap is below s^ adds the barrier of Incremental Potential
// Contact (Li et al., SIGGRAPH 2020)
//   b(s) = -kappa (s - s^)^2 ln(s / s^),  0 < s < s^,
// smooth (C2) and infinite as the layers close, so that an energy that never rises cannot bring
// two layers nearer than the thickness. Below minimumGap (1e-3 s^) it goes on as its own second
// order Taylor polynomial, so a state that starts inside the thickness has a finite energy and is
// pushed out.
//
// Pairs whose distance on the flat sheet is below `exclusion` (1.5 (thickness + s^)) are the
// sheet's own neighbourhood, not layers, and are never pairs: on the flat sheet no pair is active.
// A vertex glued to one that is that near the triangle is excluded too (across a glued seam the
// sheet is one; otherwise the barrier pushes the seam apart against the glue).
// Pairs are found with a bounding-volume hierarchy over the triangles, built for each query
// (median splits, deterministic), and listed sorted (vertex, then triangle).
//
// Solvers: the static solver adds the barrier's energy, force and Hessian b'' grad(d) grad(d)^T
// (positive semidefinite), and in its exact last stage b' Hess(d) too (by differences) and limits
// each step so that no pair can close more than 90% of its gap along it (contactStepBound: a gap
// changes at most by the largest motion of the vertex relative to the triangle's corners), so no
// vertex passes through a layer between iterations. The dynamic solver adds the same force from a
// list of pairs within the activation gap plus a skin, found again when a vertex has moved half the
// skin (ContactList), evaluating only those that can have come within the activation gap.
//
// Stiffness kappa: stiffnessScale x the hinges' force scale (the largest k / |e| over hinges, the
// static solver's forceScale) / s^; at half the activation gap a pair pushes with about 12 times
// that force.
//
// Edge-edge pairs (layer39; ContactOptions, which `simulate --paper` asks for): two bars with no
// end in common whose segments come within the thickness + s^ of each other have the same barrier
// on the segments' distance (its gradient at the nearest points, Ericson 5.1.9), excluded as
// vertex-triangle pairs are (near on the flat sheet, within 3 x exclusion for edges, or across a
// glued seam), and bound the static solver's steps alike. They keep edges from passing through
// edges, which vertex-triangle pairs cannot. Edges nearer on the flat sheet meet beside a crease,
// where the sharp fold cannot hold them a thickness apart (kEdgeExclusionScale, contact.cpp: with
// the exclusion of vertex-triangle pairs the recorded cone glued settled at 5.5% strain, 0.9%
// without edge pairs). Off by default in the engine; two settles of contact20's 126 paper runs
// stop short of the tolerance with them (residuals 1.8e-9 and 4.2e-9; the second's forces are
// under what moving a vertex by its coordinates' last place changes: contact21,
// docs/performance.md; both settle now, at the rounding floor and after a stall retried from the
// first damping: static_solver.hpp, settle22).
//
// Known limits: the distance between nearly parallel segments is not smooth (IPC's mollifier is
// not applied); the dynamic solver's step is not
// limited by the barrier's stiffness, which grows as 1 / s^2 deep in it; paper mode only (design
// mode has no thickness and keeps none).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

namespace curvefold {

struct BarHingeModel;
struct SimulationState;

// The point of triangle (a, b, c) nearest p, as barycentric weights.
glm::dvec3 nearestTriangleWeights(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                  const glm::dvec3& c);

// What ModelOptions asks for.
struct ContactOptions {
  // Off unless asked for (`simulate --paper` asks unless --no-contact): with it the static
  // solver ends short of its tolerance on patterns that fold in many layers (docs/performance.md,
  // "Self-contact in paper mode"). Paper mode only; design mode never has contact.
  bool enabled = false;
  double thickness = 0.0;        // m; 0: the paper's (PaperProperties::thickness)
  double stiffnessScale = 10.0;  // kappa = stiffnessScale x force scale / activation
  // Edge-edge pairs too (above), and with them the static solver's step bound advanced along
  // the step (contact_advance.hpp). Off here; `simulate --paper` asks for them (setPaperMode).
  // Asked for on sheets without glue no triangle pair crossed more than without in contact19's
  // 126 paper runs (1 to 625 fewer in 30), 33 more states settled, but two states that settle
  // without stopped at residuals 1.8e-9 and 4.2e-9 (the tolerance 1e-9) and strain rose in 31
  // runs (contact20, docs/performance.md). On a glued sheet only with edgePairsWhereGlued (on
  // here and in setPaperMode; the glued designs settle as without edge pairs since contact21).
  bool edgePairs = false;
  bool edgePairsWhereGlued = true;
};

// What the model keeps (BarHingeModel::contact); enabled only in paper mode with contact on.
struct ContactParameters {
  bool enabled = false;
  double thickness = 0.0;   // the smallest distance a vertex keeps from a triangle not its own
  double activation = 0.0;  // s^: the gap below which a pair pushes
  double minimumGap = 0.0;  // below this gap the barrier is its Taylor polynomial
  double stiffness = 0.0;   // kappa, N/m
  double exclusion = 0.0;   // pairs nearer than this on the flat sheet are never pairs
  bool edgePairs = false;   // ContactOptions::edgePairs
  // The dynamic solver's barrier is its Taylor polynomial below this gap (setDynamicContactStep),
  // so its stiffness stays within what the explicit step is stable at.
  double dynamicMinimumGap = 0.0;
};

// Sets dynamicMinimumGap to the gap where the barrier's b'' is `largestStiffness` (N/m): buildModel
// gives it 3/8 of the lightest vertex's mass over the step squared, the stiffness a vertex may add
// (about 8 pairs on it, each up to 1 along the distance's gradient at it and 1 summed over the
// others') and stay within the semi-implicit Euler step's stability (omega dt < 2, where the step
// is 1 / omega of the elements alone). Recompute it after changing the step.
void setDynamicContactStep(ContactParameters& contact, double largestStiffness);

// The contact of a model already built (bars and hinges): off outside paper mode or when not
// enabled.
ContactParameters contactParameters(const BarHingeModel& model, const ContactOptions& options,
                                    double paperThickness);

// A vertex and a triangle not its own, or (edges) two bars with no end in common: then `vertex`
// is the first bar and `triangle` the second (vertex < triangle).
struct ContactPair {
  std::uint8_t edges = 0;
  std::uint32_t vertex = 0, triangle = 0;
  auto operator<=>(const ContactPair&) const = default;
};

// The pair's four vertices: the vertex then the triangle's corners, or the first bar's ends then
// the second's.
std::array<std::uint32_t, 4> contactPairVertices(const BarHingeModel& model,
                                                 const ContactPair& pair);

// Every pair (excluded ones left out) whose vertex is within thickness + reach of its triangle,
// then every pair of edges as near, sorted (vertex-triangle pairs first).
std::vector<ContactPair> findContactPairs(const BarHingeModel& model,
                                          const std::vector<glm::dvec3>& positions, double reach);

// One pair's barrier at these positions: its four vertices (the vertex, then the triangle's),
// the distance's gradient with respect to each, and b, b' and b'' of its gap. False when the pair
// pushes not at all (its gap at or above the activation).
struct ContactTerm {
  std::array<std::uint32_t, 4> vertices{};
  std::array<glm::dvec3, 4> gradient{};
  double energy = 0.0, slope = 0.0, curvature = 0.0;
};
// `dynamic`: the dynamic solver's barrier (dynamicMinimumGap).
bool contactTerm(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                 const ContactPair& pair, ContactTerm& term, bool dynamic = false);

// The barrier's energy at these positions (0 when contact is off). Summed in pair order.
double contactEnergy(const BarHingeModel& model, const std::vector<glm::dvec3>& positions);

// contactEnergy(moved) - contactEnergy(positions), summed pair by pair from each pair's change of
// gap (both pieces of the barrier expanded in it): accurate where the difference of the two sums
// is rounding (a step near equilibrium changes the barrier by 1e-20 J against sums of 1e-3 J).
// Pairs within the activation gap at either positions, sorted (vertex-triangle pairs first).
double contactEnergyChange(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                           const std::vector<glm::dvec3>& moved);

// Adds each listed pair's force (minus the barrier's gradient) to vertexForces, in pair order;
// pinned vertices get none. Without a list, the pairs within the activation gap are found.
void addContactForces(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                      const std::vector<ContactPair>& pairs, std::vector<glm::dvec3>& vertexForces,
                      bool dynamic = false);
void addContactForces(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                      std::vector<glm::dvec3>& vertexForces);

// The largest share (0..1] of the step positions + step that no pair can close more than 90% of
// its gap along (pairs already inside the thickness are not counted). 1 when contact is off.
double contactStepBound(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                        const std::vector<glm::dvec3>& step);

// The dynamic solver's pairs (a Verlet list): those within the activation gap plus a skin (twice
// the activation gap: kSkinScale, contact.cpp), found again when, and only when, some vertex has
// moved more than half the skin since (a pair's distance changes at most by its vertices' two
// largest motions, so no pair outside the list can push before then). Each pair keeps its distance
// when found: a step evaluates only the pairs whose distance then, less twice the largest motion
// since, is within reach of the barrier (the others cannot push), each on all cores, and each
// vertex sums its pairs' forces in pair order (its slots, found with the list), also on all cores:
// the same bits as summing pair by pair, for any thread count. A search after the first refits the
// trees of the last (the triangles' and the bars' boxes, the splits kept: the same pairs as a tree
// built anew) while the splits stay fit (kRefitStaleness, contact.cpp), and builds them anew
// otherwise. Inputs: the model (contact enabled) and the positions; `rebuilds` counts the searches,
// `refits` those that refitted. Limits: a sheet whose vertices all move (a flap swinging as it
// folds) is searched again every skin / 2 of motion even where no layer is near; every listed pair
// within reach is evaluated each step.
struct ContactTrees;  // contact.cpp: the search's trees, kept to be refitted
struct ContactList {
  std::vector<ContactPair> pairs;
  std::vector<glm::dvec3> builtAt;
  std::size_t rebuilds = 0;
  std::size_t refits = 0;               // of the searches, those that refitted every tree
  std::vector<double> builtDistance;    // per pair: its distance when found
  double moved = 0.0;                   // the largest motion of a vertex since then
  double skin = 0.0;                    // the skin it was found with
  std::shared_ptr<ContactTrees> trees;  // shared by copies of a state until one searches
  // Scratch of the forces: per pair its four vertices' forces and whether it pushes; the
  // vertices in some pair (touched); per step on all cores, the pairs that push and per vertex
  // its run of their slots (pair * 4 + corner) in pair order.
  std::vector<std::array<glm::dvec3, 4>> forces;
  std::vector<std::uint8_t> pushing;
  std::vector<std::uint32_t> touched;
  std::vector<std::uint32_t> pushedPairs, pushOffsets, pushSlots, pushNext;
  std::size_t indexed = 0;  // the search (rebuilds) the scratch belongs to
};
// Searches again when stale (above); returns whether it did.
bool refreshContactList(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                        ContactList& list);

// The dynamic step's hook: refreshes the state's list and returns each vertex's contact force
// (state.contactForces), or null when contact is off or no pair is listed.
const glm::dvec3* dynamicContactForces(const BarHingeModel& model, SimulationState& state);

// The smallest distance between a vertex and a triangle not its own, among those nearer than
// `reach`, leaving out pairs nearer than 3 x thickness on the flat sheet (the contact's exclusion
// for that thickness); reach when there is none. Works with contact off (to measure without it).
double smallestLayerDistance(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                             double thickness, double reach);

// How many pairs of the model's triangles cross each other at these positions (the geometry
// core's self-intersection test, as `curvefold check` runs it).
std::size_t crossingTrianglePairs(const BarHingeModel& model,
                                  const std::vector<glm::dvec3>& positions);

}  // namespace curvefold
