// Deterministic procedural scenes: one time step of plausible simulator motion, for
// simulation-like CCD queries (mostly near misses, a few percent of contacts).
//
// Deterministic: the same (resolution, seed) gives bit-identical positions. The noise is drawn
// from std::mt19937_64's raw output (fully specified by the standard), not from
// std::uniform_real_distribution (implementation-defined), so it is the same with every
// standard library; the positions also use std::sqrt (correctly rounded) and std::sin/std::cos,
// whose last bit may differ between C libraries.
#pragma once

#include <cstdint>
#include <string>

#include "scene/mesh.hpp"

namespace exactccd::scene {

/// A cloth sheet (resolution x resolution quads) draped over a static icosphere: it lies on the
/// sphere's cap a small, noisy clearance above it (apart from the sphere at t0) and hangs along
/// the tangent beyond; during the step it settles onto the sphere by a noisy amount, so that
/// some vertices and edges reach the sphere.
MovingMesh cloth_on_sphere(int resolution, std::uint64_t seed);

/// A ribbon wound as a helix whose pitch tightens during the step: neighbouring turns approach
/// and, where the noisy gap closes, touch.
MovingMesh twisting_strip(int resolution, std::uint64_t seed);

/// A sheet folding about the line x = 0: the right half rotates towards the left half and
/// sinks slightly, so that parts of it cross the left half during the step.
MovingMesh folding_sheet(int resolution, std::uint64_t seed);

/// A pile of small rigid bodies (cubes and regular tetrahedra, alternating) falling onto a static
/// ground grid: three layers of resolution x resolution bodies on a jittered lattice, each layer
/// shifted by half a cell, each body resting a small noisy gap above the highest body below it
/// (or the ground) and moving down by a noisy step while turning by a small rotation.
MovingMesh falling_pile(int resolution, std::uint64_t seed);

/// A regular grid of (nx x ny) quads, two triangles each, in the plane z = 0 over
/// [x0, x1] x [y0, y1]; the same positions at t0 and t1.
MovingMesh grid(int nx, int ny, double x0, double x1, double y0, double y1);

/// An icosphere (icosahedron subdivided `levels` times) of the given radius, static.
MovingMesh icosphere(int levels, double radius);

/// The scene named "cloth", "strip", "fold" or "pile"; throws std::invalid_argument otherwise
/// (and for a resolution below 2).
MovingMesh procedural_scene(const std::string& name, int resolution, std::uint64_t seed);

}  // namespace exactccd::scene
