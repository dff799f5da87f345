#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/scene/scene.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

// Motion blur as the camera sidecar describes it:
//   "shutter": [open, close],                      (seconds; default [0, 1])
//   "motion": [{"object": "name", "velocity": [x, y, z]}, ...]   (scene units per second)
// An object is an OBJ `o`/`g` group (ScenePolygon::object). The OBJ holds each object where it
// is at time 0; at time t it is translated by velocity·t.
struct MotionSpec {
  struct Object {
    std::string name;
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
    int line = 0;  // line of the entry in the JSON file, for error messages
  };
  std::string source;  // the file it came from
  double shutterOpen = 0, shutterClose = 1;
  std::vector<Object> objects;
  bool empty() const { return objects.empty(); }
};

// Reads "shutter" and "motion" from a camera JSON file (the other keys are the camera's). A file
// without them gives an empty spec. Throws InputError naming the file and line on bad content.
MotionSpec loadMotionSpec(const std::string& path);

// The spec applied to a meshed scene: where each moving element is at the ends of the shutter.
// Shutter time τ in [0, 1] (what rays carry) is the moment open + τ·(close − open).
class SceneMotion {
 public:
  // Throws InputError when an object names no group of the scene, a moving object emits light
  // (emitters stay put: the emitter sampler draws points at rest), or a moving object shares
  // vertices with geometry that moves differently (it would tear the mesh).
  SceneMotion(const Scene& scene, const PatchMesh& mesh, const MotionSpec& spec);

  const VertexMotion& vertices() const { return vertices_; }
  Eigen::Vector3d displacement(int element, double tau) const {
    return (1 - tau) * elementOpen_[element] + tau * elementClose_[element];
  }
  int movingElements() const { return movingElements_; }

 private:
  VertexMotion vertices_;
  std::vector<Eigen::Vector3d> elementOpen_, elementClose_;
  int movingElements_ = 0;
};

}  // namespace rad
