// The bar-and-hinge model's buffers and push constants, shared by the simulation's compute
// kernels (engine/simulation_vk/gpu_dynamic_solver.hpp lays them out; bar_hinge_model.hpp
// describes the model). Single precision: see gpu_dynamic_solver.hpp.
layout(local_size_x = 64) in;

layout(push_constant) uniform Step {
  uint barCount;
  uint hingeCount;
  uint glueCount;
  uint vertexCount;
  float foldAmount;     // 0..1: driven hinges aim at target x foldAmount
  float timeStep;       // seconds
  float keep;           // 1 - the velocity damping per step
  float dampingRatio;   // of each bar
  float glueStiffness;
  uint restLengths;     // 1: the element kernel only measures the bars' rest lengths
  // A spring pulling one vertex toward a point (interaction/live_simulation.hpp's pull), as the
  // impulse pullImpulse (to - x) on its velocity before the step; pullVertex ~0u: none.
  uint pullVertex;
  float pullImpulse;
  vec3 pullTo;
} step;

// State (xyz used; w 0).
layout(std430, binding = 0) buffer Positions { vec4 positions[]; };
layout(std430, binding = 1) buffer Velocities { vec4 velocities[]; };
layout(std430, binding = 2) buffer Angles { float angles[]; };  // unwrapped, last step's
layout(std430, binding = 3) buffer SlotForces { vec4 slotForces[]; };
// The model: bars (a, b) and (rest length, stiffness, damping, 0); hinges (a, b, c, d) and
// (target at fold amount 1, driven 1 or 0, stiffness, the crease's one-sided stiffness signed by
// its side: bar_hinge_model.hpp's hingeWrongSide); glue (a, b); per vertex (first gather
// slot, past the last, pinned, mass's float bits); the gather list.
layout(std430, binding = 4) readonly buffer Bars { uvec2 bars[]; };
layout(std430, binding = 5) buffer BarParameters { vec4 barParameters[]; };
layout(std430, binding = 6) readonly buffer Hinges { uvec4 hinges[]; };
layout(std430, binding = 7) readonly buffer HingeParameters { vec4 hingeParameters[]; };
layout(std430, binding = 8) readonly buffer Glue { uvec2 glue[]; };
layout(std430, binding = 9) readonly buffer Vertices { uvec4 vertices[]; };
layout(std430, binding = 10) readonly buffer GatherSlots { uint gatherSlots[]; };

// Slots: bar i's ends at 2i, 2i + 1; hinge j's a, b, c, d at hingeSlot0() + 4j..; glue g's at
// glueSlot0() + 2g.
uint hingeSlot0() { return 2u * step.barCount; }
uint glueSlot0() { return hingeSlot0() + 4u * step.hingeCount; }

// Every invocation of a dispatch of N workgroups visits index, index + 64 N, ...: a dispatch
// stays within the 65,535 workgroups every device allows however many elements there are.
uint dispatchStride() { return gl_NumWorkGroups.x * gl_WorkGroupSize.x; }

// The velocity a step starts from: the stored one, and the pulled vertex's with the spring's
// impulse (the CPU path adds it to the stored velocity before the step, which both kernels read).
vec3 startVelocity(uint v) {
  vec3 velocity = velocities[v].xyz;
  if (v == step.pullVertex) velocity += step.pullImpulse * (step.pullTo - positions[v].xyz);
  return velocity;
}
