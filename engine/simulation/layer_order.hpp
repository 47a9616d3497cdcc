// Layers that start in touch (paper mode's self-contact, contact.hpp). A design folds flaps flat
// onto the sheet (reflection makes folds of exactly 180 degrees), so a vertex can lie on a layer
// of the sheet where paper of a thickness cannot be; at a distance of 0 the barrier cannot tell
// which side of the layer the vertex belongs on and pushes some out the wrong way (the recorded
// cone glued: 10 crossing pairs, residual 5e4, NOT settled).
//
// layerSide: the side of triangle t vertex v belongs on (+1: along the triangle's normal
// (b - a) x (c - a), -1 against it). Where the vertex is off the triangle by more than rounding
// (1e-3 of the thickness: a fold short of flat tilts its flap off the layer) the side it is on.
// Else the layer order of the folds between them: each nearly flat fold (|angle| >= 170 degrees,
// then >= 90 if none is) on the shortest path of triangles from t to a triangle of v is opened a
// little, every one by the same small angle toward 0, and the vertex belongs on the side that
// moves it to (a valley brings fronts together: a flap folded flat by a valley lies on the front
// of the sheet, by a mountain on its back). +1 when neither tells.
//
// separateLayers: every pair (contact.hpp's, exclusions kept) whose vertex is within the
// thickness of its triangle gets its side, then a few sweeps of projections move the vertex
// and the triangle apart along the triangle's normal until each such pair is thickness + half
// the activation gap apart on its side (the correction shared by the vertex and the triangle's
// corners by their weights at the nearest point; pinned vertices stay). From there the
// barrier, whose steps never pass a layer (contactStepBound), keeps every pair on the side chosen:
// a one-sided barrier for the pairs that started in touch, with the energy unchanged.
//
// Limits: the sides are those of the path's folds alone; a vertex between two layers that both
// start in touch with it is pushed by both and may stay within the thickness (sweeps end at 20).
// Contact enabled only (does nothing otherwise).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/simulation/bar_hinge_model.hpp"

namespace curvefold {

int layerSide(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
              const std::vector<double>& hingeAngles, std::uint32_t vertex, std::uint32_t triangle);

struct LayerSeparation {
  std::size_t pairs = 0;   // pairs found within the thickness (each given its side)
  std::size_t sweeps = 0;  // projection sweeps run
  std::size_t left = 0;    // pairs still nearer than the thickness after them
};

// Moves the positions so that no pair is within the thickness (above); hingeAngles (one per hinge,
// unwrapped) are the state's, for the folds' sides.
LayerSeparation separateLayers(const BarHingeModel& model, std::vector<glm::dvec3>& positions,
                               const std::vector<double>& hingeAngles);

// separateLayers, made again where the separated positions pass the sheet through itself
// (crossingTrianglePairs, contact.hpp) and the given ones did not: a side the path's folds chose
// wrongly (xr_studio glued: 3 pairs in touch became 3 crossing pairs). Each pair with its vertex
// or triangle among the crossing triangles takes the other side and the separation runs again
// from the given positions, up to three times; what then still crosses is undone (the positions
// left as given: the layers in touch, which the barrier pushes apart blind to their sides, and
// xr_studio's settle from there ended with 18 pairs crossing). The static solver's guard on each
// predictor guess. True when the positions were moved (some pair was within the thickness and a
// separation kept); the caller recomputes the hinge angles then.
bool separateLayersUnlessCrossing(const BarHingeModel& model, std::vector<glm::dvec3>& positions,
                                  const std::vector<double>& hingeAngles);

}  // namespace curvefold
