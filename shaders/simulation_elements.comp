#version 450
#extension GL_GOOGLE_include_directive : require
// The bar-and-hinge model's element forces (engine/simulation/bar_hinge_model.cpp's
// elementForces, in single precision): each bar, hinge and glue pair writes its force on each of
// its vertices into its own slots; the vertex kernel sums them. No atomics: the same bits on the
// same device every run.
#include "simulation_layout.glsl"

const float kPi = 3.14159265358979;

// previous + (raw - previous) wrapped to [-pi, pi] (the CPU's unwrapAgainst).
float unwrapAgainst(float raw, float previous) {
  float change = raw - previous;
  if (abs(change) > kPi) change -= 2.0 * kPi * roundEven(change / (2.0 * kPi));
  return previous + change;
}

void barForce(uint i) {
  const uvec2 bar = bars[i];
  precise const vec3 delta = positions[bar.y].xyz - positions[bar.x].xyz;
  precise const float length = sqrt(dot(delta, delta));
  // Measured by this same expression, the flat state's rest lengths make it exactly at rest.
  if (step.restLengths != 0u) {
    barParameters[i].x = length;
    return;
  }
  const vec4 bar4 = barParameters[i];  // rest length, stiffness, damping
  vec3 force = vec3(0.0);  // on a; b gets the opposite
  if (length > 0.0) {
    precise const float stretch = length - bar4.x;
    float pull = bar4.y * stretch;
    pull += step.dampingRatio * bar4.z *
            dot(startVelocity(bar.y) - startVelocity(bar.x), delta) / length;
    force = (pull / length) * delta;
  }
  slotForces[2u * i] = vec4(force, 0.0);
  slotForces[2u * i + 1u] = vec4(-force, 0.0);
}

// The signed dihedral angle (positive valley) unwrapped against the last one, and its gradient
// (bar_hinge_model.cpp's angleWithGradient).
void hingeForce(uint j) {
  const uvec4 h = hinges[j];
  const vec3 a = positions[h.x].xyz, b = positions[h.y].xyz;
  const vec3 c = positions[h.z].xyz, d = positions[h.w].xyz;
  const vec3 edge = b - a;
  const vec3 n1 = cross(edge, c - a);
  const vec3 n2 = cross(a - b, d - b);
  const float n1n1 = dot(n1, n1), n2n2 = dot(n2, n2), ee = dot(edge, edge);
  const float previous = angles[j];
  float angle = previous;
  vec3 ga = vec3(0.0), gb = vec3(0.0), gc = vec3(0.0), gd = vec3(0.0);
  if (n1n1 > 0.0 && n2n2 > 0.0 && ee > 0.0) {
    const float length = sqrt(ee);
    const float sine = -dot(cross(n1, n2), edge) / length;
    const float cosine = dot(n1, n2);
    // GLSL's atan(y, x) is undefined at (0, 0); the CPU's gives 0 there.
    const float raw = sine == 0.0 && cosine == 0.0 ? 0.0 : atan(sine, cosine);
    angle = unwrapAgainst(raw, previous);
    // A wing moving along its face's normal turns the face by 1 / its height; the edge's ends
    // share the rest so the gradient is blind to translation and rotation.
    gc = n1 * (length / n1n1);
    gd = n2 * (length / n2n2);
    const float tc = dot(c - a, edge) / ee;
    const float td = dot(d - a, edge) / ee;
    ga = -(1.0 - tc) * gc - (1.0 - td) * gd;
    gb = -tc * gc - td * gd;
  }
  angles[j] = angle;
  const vec4 hinge4 = hingeParameters[j];  // target, driven, stiffness, signed one-sided stiffness
  const float target = hinge4.y != 0.0 ? hinge4.x * step.foldAmount : hinge4.x;
  // A crease kept on its side of flat and short of passing flat-folded (hinge_kernel.hpp's
  // wrongSideExcess): q along its side, the distance past 0 or pi, times its one-sided stiffness.
  const float q = sign(hinge4.w) * angle;
  const float excess = min(q, 0.0) + max(q - kPi, 0.0);
  const float torque = -(hinge4.z * (angle - target) + hinge4.w * excess);
  const uint slot = hingeSlot0() + 4u * j;
  slotForces[slot] = vec4(torque * ga, 0.0);
  slotForces[slot + 1u] = vec4(torque * gb, 0.0);
  slotForces[slot + 2u] = vec4(torque * gc, 0.0);
  slotForces[slot + 3u] = vec4(torque * gd, 0.0);
}

void glueForce(uint g) {
  const uvec2 pair = glue[g];
  const vec3 force = step.glueStiffness * (positions[pair.y].xyz - positions[pair.x].xyz);
  slotForces[glueSlot0() + 2u * g] = vec4(force, 0.0);
  slotForces[glueSlot0() + 2u * g + 1u] = vec4(-force, 0.0);
}

void main() {
  const uint count = step.restLengths != 0u ? step.barCount
                                            : step.barCount + step.hingeCount + step.glueCount;
  for (uint e = gl_GlobalInvocationID.x; e < count; e += dispatchStride()) {
    if (e < step.barCount)
      barForce(e);
    else if (e < step.barCount + step.hingeCount)
      hingeForce(e - step.barCount);
    else
      glueForce(e - step.barCount - step.hingeCount);
  }
}
