// The One Euro filter (Casiez, Roussel and Vogel, CHI 2012; https://gery.casiez.net/1euro/): a
// first-order low-pass filter whose cutoff rises with the signal's speed, so a value at rest is
// steady and a moving one is not left behind. One implementation for every kind of value: a number,
// a point (glm::dvec3) and an orientation (glm::dquat, stepped by slerp, its speed the angular
// velocity, a vector). tests/test_one_euro_filter.cpp checks it against the reference
// implementation's published data.
#pragma once

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

namespace curvefold {

struct OneEuroParameters {
  double minCutoff = 1.0;         // Hz: the cutoff at rest
  double beta = 0.0;              // how fast the cutoff rises with speed (Hz per unit per second)
  double derivativeCutoff = 1.0;  // Hz: the cutoff of the speed estimate
};

// The smoothing factor of a first-order low-pass filter with this cutoff (Hz), for a step of dt
// seconds: the share of the way from the last output to the new sample.
double lowPassSmoothing(double cutoffHz, double dt);

// How the filter treats a kind of value: how far a sample moved from the last output (its rate is
// that over dt, smoothed as is), that rate's size, and a step of `smoothing` of the way towards
// the sample.
template <typename Value>
struct OneEuroValue;

template <>
struct OneEuroValue<double> {
  using Change = double;
  static double change(double from, double to) { return to - from; }
  static double size(double rate) { return std::abs(rate); }
  static double step(double from, double to, double smoothing) {
    return from + smoothing * (to - from);
  }
};

template <>
struct OneEuroValue<glm::dvec3> {
  using Change = glm::dvec3;
  static glm::dvec3 change(const glm::dvec3& from, const glm::dvec3& to) { return to - from; }
  static double size(const glm::dvec3& rate) { return glm::length(rate); }
  static glm::dvec3 step(const glm::dvec3& from, const glm::dvec3& to, double smoothing) {
    return from + smoothing * (to - from);
  }
};

// An orientation's change is the turn that takes it there, as a rotation vector (axis times angle,
// radians, in the world frame), the shorter way round. A vector, not the angle alone: jitter at
// rest turns one way, then back, and its mean speed must average out to zero as a point's does,
// or the cutoff would rise at rest (with a rotation beta of 10, the filter would then pass the
// jitter through).
template <>
struct OneEuroValue<glm::dquat> {
  using Change = glm::dvec3;
  static glm::dvec3 change(const glm::dquat& from, const glm::dquat& to);
  static double size(const glm::dvec3& rate) { return glm::length(rate); }
  static glm::dquat step(const glm::dquat& from, const glm::dquat& to, double smoothing);
};

// The filter. The first sample (and the first after reset) passes through with a speed of zero;
// each later one at a later time moves the output by lowPassSmoothing(cutoff, dt) of the way to it,
// where cutoff = minCutoff + beta * |speed| and the speed (the change from the last *output* over
// dt) is itself low-passed at derivativeCutoff, as in the reference since 2023. A sample at the
// same time as the last (or earlier) changes nothing and gets the last output back.
template <typename Value>
class OneEuroFilter {
 public:
  using Traits = OneEuroValue<Value>;
  using Change = typename Traits::Change;

  explicit OneEuroFilter(const OneEuroParameters& parameters) : parameters_(parameters) {}

  // The filtered value for a sample at `time` (seconds).
  Value filter(const Value& sample, double time) {
    if (!started_) {
      started_ = true;
      last_ = sample;
      rate_ = Change(0.0);
      lastTime_ = time;
      return sample;
    }
    const double dt = time - lastTime_;
    if (!(dt > 0.0)) return last_;  // the same instant again: nothing new to smooth
    lastTime_ = time;
    const Change rate = Traits::change(last_, sample) / dt;
    rate_ += lowPassSmoothing(parameters_.derivativeCutoff, dt) * (rate - rate_);
    const double cutoff = parameters_.minCutoff + parameters_.beta * Traits::size(rate_);
    last_ = Traits::step(last_, sample, lowPassSmoothing(cutoff, dt));
    return last_;
  }
  void reset() { started_ = false; }

 private:
  OneEuroParameters parameters_;
  bool started_ = false;
  Value last_{};      // the last output, once started
  Change rate_{0.0};  // the low-passed speed
  double lastTime_ = 0.0;
};

}  // namespace curvefold
