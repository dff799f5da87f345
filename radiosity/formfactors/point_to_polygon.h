#pragma once

#include <Eigen/Core>
#include <vector>

namespace rad {

// Exact differential-area-to-polygon form factor (Lambert; Nusselt's analogue): the fraction of
// the energy leaving a point p with unit normal n that reaches the polygon, ignoring occlusion:
//
//   F = (1/2π) Σ_i β_i (n · Γ_i),  Γ_i = unit(R_i × R_{i+1}),  β_i = angle(R_i, R_{i+1}),  R_i =
//   v_i − p
//
// The polygon (planar, any winding) is first clipped to the half-space above p's tangent plane,
// since the formula holds only for what p can see. A polygon whose front (counter-clockwise side)
// faces away from p gives 0: emitters and receivers are one-sided. When p lies on one of the
// polygon's edges (a receiver sharing an edge with the source), that edge's term is replaced by
// its limit as p approaches from the side the polygon faces, which keeps F finite and continuous.
double pointToPolygonFormFactor(const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                                const std::vector<Eigen::Vector3d>& polygon);

}  // namespace rad
