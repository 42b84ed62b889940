// Deterministic procedural scenes: one time step of plausible simulator motion, for
// simulation-like CCD queries (mostly near misses, a few percent of contacts).
#pragma once

#include <cstdint>
#include <string>

#include "scene/mesh.hpp"

namespace exactccd::scene {

/// A cloth sheet (resolution x resolution quads) draped over a static icosphere; the sheet sits
/// a small, noisy gap above the sphere's cap and moves down by a noisy step, so that some
/// vertices cross the sphere's surface during the step.
MovingMesh cloth_on_sphere(int resolution, std::uint64_t seed);

/// A ribbon wound as a helix whose pitch tightens during the step: neighbouring turns approach
/// and, where the noisy gap closes, touch.
MovingMesh twisting_strip(int resolution, std::uint64_t seed);

/// A sheet folding about the line x = 0: the right half rotates towards the left half and
/// sinks slightly, so that parts of it cross the left half during the step.
MovingMesh folding_sheet(int resolution, std::uint64_t seed);

/// A regular grid of (nx x ny) quads, two triangles each, in the plane z = 0 over
/// [x0, x1] x [y0, y1]; the same positions at t0 and t1.
MovingMesh grid(int nx, int ny, double x0, double x1, double y0, double y1);

/// An icosphere (icosahedron subdivided `levels` times) of the given radius, static.
MovingMesh icosphere(int levels, double radius);

/// The scene named "cloth", "strip" or "fold"; throws std::invalid_argument otherwise.
MovingMesh procedural_scene(const std::string& name, int resolution, std::uint64_t seed);

}  // namespace exactccd::scene
