#pragma once

#include <Eigen/Core>

#include "radiosity/scene/camera.h"

class vtkCamera;

namespace rad {

// The scene's camera (radiosity/scene/camera.h: cameraSidecarPath, loadCamera, findSceneCamera)
// is the viewer's camera too; the viewer uses its position, look_at, up and vertical field of
// view (the window, not the camera's width and height, sets the aspect; no lens).

// A camera that frames the box [min, max]: it looks along `direction` (need not be unit) at the
// box's centre from far enough that the bounding sphere fits the field of view at `aspect`
// (width / height). Up is +y, or +z when looking along y.
Camera frameBounds(const Eigen::Vector3d& min, const Eigen::Vector3d& max,
                   const Eigen::Vector3d& direction, double aspect, double vfovDegrees = 30);

// Points VTK's camera as `camera` looks: position, focal point, view up (made orthogonal to the
// view) and vertical view angle.
void applyToView(const Camera& camera, vtkCamera& view);

}  // namespace rad
