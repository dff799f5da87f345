#pragma once

#include <Eigen/Core>
#include <array>

#include "radiosity/scene/lights.h"

namespace rad {

// The box an edit occupies: the bounds of the moved, added and removed elements, old places and
// new (update, incremental_update.h).
struct EditBox {
  Eigen::Vector3d lo, hi;
};

// Whether some shadow ray that DirectLightStage casts from the element (`corners`, front
// `normal`) toward `light` may meet `box`: when not, the edit cannot change the element's direct
// light from it, and update keeps the value the kept solve computed. Conservative: true wherever
// it cannot be ruled out, with `margin` (scene units, beyond the rays' lift-off) to spare.
//  - point and spot lights: the segments to the lamp stay in the box around the element and it;
//  - directional lights: the rays stay in the element's bounding sphere swept toward the sun,
//    widening by the disc's half-angle;
//  - skies: the rays leave into the front half-space and upward (the ground below the horizon is
//    black and casts none), so a box behind the element's plane or wholly below it is not met;
//  - environments: the front half-space (the whole sphere shines).
bool shadowRaysMayMeet(const Light& light, const std::array<Eigen::Vector3d, 3>& corners,
                       const Eigen::Vector3d& normal, const EditBox& box, double margin);

// Whether some ray from a point of the element along `direction` (ElementExposure's probes) may
// meet `box`: the rays stay in the element's bounding sphere swept along it. Conservative, as
// shadowRaysMayMeet.
bool raysAlongMayMeet(const std::array<Eigen::Vector3d, 3>& corners,
                      const Eigen::Vector3d& direction, const EditBox& box, double margin);

}  // namespace rad
