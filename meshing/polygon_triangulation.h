#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace rad {

// Splits a simple polygon (possibly non-convex, possibly slightly non-planar) into triangles by
// ear clipping in the plane of its Newell normal. Returns index triples into `polygon`, keeping
// its winding. Degenerate ears (zero area) are dropped.
std::vector<std::array<int, 3>> triangulatePolygon(const std::vector<Eigen::Vector3d>& polygon);

// Newell's method: robust normal (times twice the area) of a possibly non-planar polygon.
Eigen::Vector3d newellNormal(const std::vector<Eigen::Vector3d>& polygon);

}  // namespace rad
