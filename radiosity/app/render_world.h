#pragma once

#include <memory>
#include <string>
#include <vector>

#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solution_source.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/render/render_methods.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/render/scene_motion.h"

namespace rad {

// The scene as each render method needs it, built once on first use and shared: the loaded and
// meshed scene with its BVH (every method), the radiosity solution on its refined mesh (methods
// that need the solve), and a motion-blur BVH (methods that render motion, when the camera file
// gives any).
class RenderWorld {
 public:
  // `cameraFile`: the camera JSON the render uses ("" for none); its "shutter"/"motion" are read
  // (and checked) at once, before any long work. `source`: where a saved solution may come from
  // (solution_source.h); by default every method that needs one solves.
  RenderWorld(SolveOptions solve, const std::string& cameraFile, SolutionSource source = {});
  ~RenderWorld();

  struct View {
    const RenderScene* scene = nullptr;
    const std::vector<Rgb>* radiosity = nullptr;         // with the solve only
    const std::vector<Rgb>* directIrradiance = nullptr;  // the solve's E_d, with `radiosity`
  };
  View viewFor(const RenderMethod& method);

  const SolveResult* solved() const { return solved_.get(); }  // null until a method needs it
  bool reusedSolution() const { return solved_ && solved_->report.reusedSavedSolution; }
  const MotionSpec& motionSpec() const { return motionSpec_; }
  const std::vector<SkipNote>& skipped() const { return skipped_; }
  double solveSeconds() const { return solveSeconds_; }
  double bvhSeconds() const { return bvhSeconds_; }

 private:
  void skip(const std::string& what, const std::string& why);
  SolveOptions solve_;
  SolutionSource source_;
  MotionSpec motionSpec_;
  std::vector<SkipNote> skipped_;
  double solveSeconds_ = 0, bvhSeconds_ = 0;
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<PatchMesh> mesh_;
  std::unique_ptr<RayCaster> caster_, motionCaster_, solvedCaster_;
  std::unique_ptr<SceneMotion> motion_;
  std::unique_ptr<RenderScene> view_, motionView_, solvedView_;
  std::unique_ptr<SolveResult> solved_;
};

}  // namespace rad
