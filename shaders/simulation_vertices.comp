#version 450
#extension GL_GOOGLE_include_directive : require
// Each vertex sums its slots in the gather list's fixed order and moves by semi-implicit Euler
// (engine/simulation/dynamic_solver.cpp's stepDynamic): v = (v + dt F / m) keep, x += dt v.
// Pinned vertices stay. A pulled vertex starts from its velocity with the pull's impulse.
#include "simulation_layout.glsl"

void main() {
  for (uint v = gl_GlobalInvocationID.x; v < step.vertexCount; v += dispatchStride()) {
    const uvec4 vertex = vertices[v];  // first slot, past the last, pinned, mass bits
    if (vertex.z != 0u) continue;
    vec3 total = vec3(0.0);
    for (uint s = vertex.x; s < vertex.y; ++s) total += slotForces[gatherSlots[s]].xyz;
    const float mass = uintBitsToFloat(vertex.w);
    const vec3 velocity = (startVelocity(v) + (step.timeStep / mass) * total) * step.keep;
    velocities[v] = vec4(velocity, 0.0);
    positions[v] = vec4(positions[v].xyz + step.timeStep * velocity, 0.0);
  }
}
